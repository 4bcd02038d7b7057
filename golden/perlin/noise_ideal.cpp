#include "perlin/noise_ideal.hpp"

#include <cmath>
#include <cstdint>

#include "perlin/noise.hpp"

namespace tmu::perlin::ideal {
namespace {

double sm(double t) { return t * t * (3 - 2 * t); }
double mix(double a, double b, double c) { return a + c * (b - a); }
uint32_t lattice_index(double floor_x) {
  return static_cast<uint32_t>(static_cast<int64_t>(floor_x)) & ((1u << kLatticeBits) - 1);
}

}  // namespace

double noise(double u, double v, double w) {
  const double fu = std::floor(u), fv = std::floor(v), fw = std::floor(w);
  const uint32_t iu = lattice_index(fu), iv = lattice_index(fv), iw = lattice_index(fw);
  const double cu = sm(u - fu), cv = sm(v - fv), cw = sm(w - fw);
  const auto r = [&](uint32_t du, uint32_t dv, uint32_t dw) {
    return lattice_value(iu + du, iv + dv, iw + dw) / 128.0;
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
