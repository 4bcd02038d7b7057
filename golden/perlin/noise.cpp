#include "perlin/noise.hpp"

#include <bit>
#include <stdexcept>
#include <string>

#include "common/error.hpp"

namespace tmu::perlin {
namespace {

constexpr uint32_t kLatticeMask = (1u << kLatticeBits) - 1;

// A coordinate at F fraction bits: the lattice index mod 2^12 and the fraction.
struct Split {
  uint32_t index = 0;
  uint32_t frac = 0;
};
Split split(int64_t raw, int frac_bits) {
  const int64_t t = raw >> (kCoordFracBits - frac_bits);  // floor
  return {static_cast<uint32_t>(t >> frac_bits) & kLatticeMask,
          static_cast<uint32_t>(t & ((int64_t{1} << frac_bits) - 1))};
}

}  // namespace

void check(const NoiseConfig& c) {
  const auto in_range = [](const char* name, int64_t value, int64_t lo, int64_t hi) {
    check_range("noise", name, value, lo, hi);
  };
  in_range("frac_bits F", c.frac_bits, 1, kCoordFracBits);
  in_range("fade_index_bits S", c.fade_index_bits, 1, c.frac_bits);
  in_range("fade_bits B", c.fade_bits, 2, 12);
  in_range("lerp_extra_bits X", c.lerp_extra_bits, 0, 8);
}

namespace {

uint32_t scramble(uint32_t x) {
  uint32_t y = 0;
  for (int j = 0; j < kLatticeBits; ++j)
    y |= static_cast<uint32_t>(std::popcount(x & kXorRows[static_cast<size_t>(j)]) & 1) << j;
  return y;
}

// T for every 12-bit value, computed once: the model's speed, not its definition.
const std::array<uint16_t, 1u << kLatticeBits>& scramble_table() {
  static const auto table = [] {
    std::array<uint16_t, 1u << kLatticeBits> t{};
    for (uint32_t x = 0; x < t.size(); ++x) t[x] = static_cast<uint16_t>(scramble(x));
    return t;
  }();
  return table;
}

}  // namespace

uint32_t xor_table(uint32_t x) { return scramble_table()[x & kLatticeMask]; }

int32_t lattice_value(uint32_t x1, uint32_t x2, uint32_t x3) {
  uint32_t h = xor_table(x1 & kLatticeMask);
  h = xor_table((h + x2) & kLatticeMask);
  h = xor_table((h + x3) & kLatticeMask);
  h = xor_table((h + x3) & kLatticeMask);
  const auto top = static_cast<int32_t>(h >> (kLatticeBits - kLatticeValueBits));
  return top >= 128 ? top - 256 : top;
}

uint32_t fade_entry(const NoiseConfig& c, uint32_t k) {
  const int s = c.fade_index_bits;
  const uint64_t kk = k;
  const uint64_t num = ((3 * kk * kk << s) - 2 * kk * kk * kk) << c.fade_bits;
  return static_cast<uint32_t>((num + (uint64_t{1} << (3 * s - 1))) >> (3 * s));
}

int32_t lerp(int32_t a, int32_t b, uint32_t c, int fade_bits) {
  const int64_t product = static_cast<int64_t>(c) * (int64_t{b} - a);
  return a + static_cast<int32_t>((product + (int64_t{1} << (fade_bits - 1))) >> fade_bits);
}

int32_t noise(const NoiseConfig& c, int64_t u, int64_t v, int64_t w) {
  const Split su = split(u, c.frac_bits), sv = split(v, c.frac_bits), sw = split(w, c.frac_bits);
  const int drop = c.frac_bits - c.fade_index_bits;
  const uint32_t fu = fade_entry(c, su.frac >> drop), fv = fade_entry(c, sv.frac >> drop),
                 fw = fade_entry(c, sw.frac >> drop);
  const auto value = [&](uint32_t du, uint32_t dv, uint32_t dw) {
    return lattice_value(su.index + du, sv.index + dv, sw.index + dw) * (1 << c.lerp_extra_bits);
  };
  const int b = c.fade_bits;
  const int32_t x00 = lerp(value(0, 0, 0), value(1, 0, 0), fu, b);
  const int32_t x10 = lerp(value(0, 1, 0), value(1, 1, 0), fu, b);
  const int32_t x01 = lerp(value(0, 0, 1), value(1, 0, 1), fu, b);
  const int32_t x11 = lerp(value(0, 1, 1), value(1, 1, 1), fu, b);
  const int32_t y0 = lerp(x00, x10, fv, b), y1 = lerp(x01, x11, fv, b);
  return lerp(y0, y1, fw, b);
}

FractalSums fractal_sums(const NoiseConfig& c, int64_t u, int64_t v, int64_t w) {
  FractalSums s;
  for (int i = 0; i < kOctaves; ++i) {
    // Octave i at 2^i (u, v, w): a multiplication, so that negative coordinates scale too.
    const int64_t scale = int64_t{1} << i;
    const int32_t p = noise(c, u * scale, v * scale, w * scale);
    s.fractal_sum += p * (1 << (kOctaves - 1 - i));
    s.turbulence += (p < 0 ? -p : p) * (1 << (kOctaves - 1 - i));
  }
  return s;
}

FractalSums port_sums(const NoiseConfig& c, const FractalSums& s) {
  constexpr int kPortX = 4;
  const int d = c.lerp_extra_bits - kPortX;
  const auto convert = [d](int32_t v) { return d > 0 ? (v + (1 << (d - 1))) >> d : v * (1 << -d); };
  return {convert(s.fractal_sum), convert(s.turbulence)};
}

}  // namespace tmu::perlin
