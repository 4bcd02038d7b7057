#include "perlin/materials_ideal.hpp"

#include <algorithm>
#include <cmath>

#include "perlin/noise_ideal.hpp"

namespace tmu::perlin::ideal {
namespace {

double q8(int64_t raw) { return static_cast<double>(raw) / 256.0; }  // UQ8.8, SQ8.8, IQ7.8

uint32_t level(double f, uint32_t gain) {
  return static_cast<uint32_t>(std::clamp(std::floor(f * q8(gain)), 0.0, 255.0));
}

}  // namespace

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
    case MaterialKind::kBrick: {
      const double s = 4096.0;  // the brick test is geometry: exact on the raw grid already
      const bool brick = in_brick(r, static_cast<int64_t>(std::floor(u * s)),
                                  static_cast<int64_t>(std::floor(v * s)));
      return entry(brick ? tables.main : tables.mortar);
    }
    default:
      return entry(tables.main);
  }
}

}  // namespace tmu::perlin::ideal
