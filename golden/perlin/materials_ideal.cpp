#include "perlin/materials_ideal.hpp"

#include <algorithm>
#include <cmath>

#include "perlin/noise_definition.hpp"
#include "perlin/noise_ideal.hpp"

namespace tmu::perlin::ideal {
namespace {

double q8(int64_t raw) { return static_cast<double>(raw) / 256.0; }  // UQ8.8, SQ8.8, IQ7.8
// The brick registers' raw units (SolidCoord's LSB) in units.
double solid(int64_t raw) { return std::ldexp(static_cast<double>(raw), -kCoordFracBits); }

uint32_t level(double f, uint32_t gain) {
  return static_cast<uint32_t>(std::clamp(std::floor(f * q8(gain)), 0.0, 255.0));
}

}  // namespace

bool in_brick(const MaterialRegs& r, double u, double v) {
  const double pw = solid(int64_t{1} << r.pw), ph = solid(int64_t{1} << r.ph);
  const double mw = solid(r.mortar_w), mh = solid(r.mortar_h);
  const double row = std::floor(v / ph);
  // An even row is shifted by half a period (fmod keeps the sign: -0 for row -2, -1 for -1).
  const double shifted = std::fmod(row, 2.0) == 0 ? u + pw / 2 : u;
  const double ur = shifted - pw * std::floor(shifted / pw), vr = v - ph * row;
  return mw < ur && ur < pw - mw && mh < vr && vr < ph - mh;
}

double material_index(const MaterialRegs& r, double u, double v, double w) {
  switch (r.kind) {
    case MaterialKind::kMarble:
      return fractal_sums(u, v, w).turbulence * q8(r.g_t) + v * q8(r.g_v);
    case MaterialKind::kWood:
      return (u * u + v * v) * q8(r.g_r) + w * q8(r.g_w) +
             fractal_sums(u, v, w).turbulence * q8(r.g_t);
    case MaterialKind::kBrick:
      return fractal_sums(u, v, w).turbulence * q8(r.g_t);
    case MaterialKind::kFire:
      return fractal_sums(u, std::exp(-std::max(v, 0.0)), w).fractal_sum * q8(r.g_t) + q8(r.offset);
    default:
      return 0;
  }
}

uint32_t shade_material(const MaterialRegs& r, const ColourTables& tables, double u, double v,
                        double w) {
  const auto entry = [&](const std::array<uint32_t, kColourEntries>& table) {
    const double i = std::floor(material_index(r, u, v, w));
    const int64_t k =
        r.kind == MaterialKind::kFire
            ? static_cast<int64_t>(std::clamp(i, 0.0, kColourEntries - 1.0))
            : ((static_cast<int64_t>(i) % kColourEntries) + kColourEntries) % kColourEntries;
    return table[static_cast<size_t>(k)];
  };
  switch (r.kind) {
    case MaterialKind::kFog: {
      const uint32_t l = level(std::abs(fractal_sums(u, v, w).fractal_sum), r.g_l);
      return (l << 16) | (l << 8) | l;
    }
    case MaterialKind::kCloud: {
      const double f = fractal_sums(2 * u, v, w).fractal_sum;
      const uint32_t l = f > r.cutoff / 16384.0 ? level(f, r.g_l) : 0;
      return (l << 16) | (l << 8) | 0xFF;
    }
    case MaterialKind::kBrick:
      return entry(in_brick(r, u, v) ? tables.main : tables.mortar);
    default:
      return entry(tables.main);
  }
}

}  // namespace tmu::perlin::ideal
