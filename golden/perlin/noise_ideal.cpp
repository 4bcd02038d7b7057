#include "perlin/noise_ideal.hpp"

#include <array>
#include <cmath>

#include "perlin/noise_definition.hpp"

namespace tmu::perlin::ideal {
namespace {

constexpr int64_t kPeriod = int64_t{1} << kLatticeBits;

// Column k of T: bit j is bit k of row j. T(x) is then the xor of the columns of x's set bits,
// the matrix product over GF(2) taken by columns (golden takes each row's parity): two ways
// to the same definition, so that a slip in either shows in tests/perlin_test.cpp.
constexpr std::array<uint32_t, kLatticeBits> columns() {
  std::array<uint32_t, kLatticeBits> c{};
  for (int k = 0; k < kLatticeBits; ++k) {
    for (int j = 0; j < kLatticeBits; ++j) {
      c[static_cast<size_t>(k)] |= ((kXorRows[static_cast<size_t>(j)] >> k) & 1u) << j;
    }
  }
  return c;
}
constexpr std::array<uint32_t, kLatticeBits> kColumns = columns();

// A lattice index mod 2^12, for negative indices too.
uint32_t wrap(int64_t i) { return static_cast<uint32_t>(((i % kPeriod) + kPeriod) % kPeriod); }

double sm(double t) { return t * t * (3 - 2 * t); }
double mix(double a, double b, double c) { return a + c * (b - a); }

}  // namespace

uint32_t scramble(uint32_t x) {
  uint32_t y = 0;
  for (int k = 0; k < kLatticeBits; ++k) {
    if ((x >> k) & 1u) y ^= kColumns[static_cast<size_t>(k)];
  }
  return y;
}

double lattice_value(int64_t i, int64_t j, int64_t k) {
  // The chain of noise_definition.hpp: the last index is added twice.
  uint32_t h = scramble(wrap(i));
  for (const uint32_t addend : {wrap(j), wrap(k), wrap(k)}) h = scramble(wrap(int64_t{h} + addend));
  // The top kLatticeValueBits bits of h as a two's complement number over 2^(bits - 1).
  const double half = std::ldexp(1.0, kLatticeValueBits - 1);
  const double top = std::floor(std::ldexp(h, kLatticeValueBits - kLatticeBits));
  return (top < half ? top : top - 2 * half) / half;
}

double noise(double u, double v, double w) {
  const double fu = std::floor(u), fv = std::floor(v), fw = std::floor(w);
  const auto iu = static_cast<int64_t>(fu), iv = static_cast<int64_t>(fv),
             iw = static_cast<int64_t>(fw);
  const double cu = sm(u - fu), cv = sm(v - fv), cw = sm(w - fw);
  const auto r = [&](int64_t du, int64_t dv, int64_t dw) {
    return lattice_value(iu + du, iv + dv, iw + dw);
  };
  const double y0 = mix(mix(r(0, 0, 0), r(1, 0, 0), cu), mix(r(0, 1, 0), r(1, 1, 0), cu), cv);
  const double y1 = mix(mix(r(0, 0, 1), r(1, 0, 1), cu), mix(r(0, 1, 1), r(1, 1, 1), cu), cv);
  return mix(y0, y1, cw);
}

FractalSums fractal_sums(double u, double v, double w) {
  FractalSums s;
  for (int i = 0; i < kOctaves; ++i) {
    const double scale = std::ldexp(1.0, i);
    const double p = noise(u * scale, v * scale, w * scale);
    s.fractal_sum += p / scale;
    s.turbulence += std::abs(p) / scale;
  }
  return s;
}

}  // namespace tmu::perlin::ideal
