#include "perlin/materials.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/error.hpp"
#include "perlin/material_unit.hpp"

namespace tmu::perlin {
namespace {

constexpr int64_t kIndexMask = (int64_t{1} << kIndexBits) - 1;

uint32_t level(int64_t f, uint32_t gain) {
  return static_cast<uint32_t>(std::clamp<int64_t>((f * gain) >> 22, 0, 255));
}

// The coordinates are SolidCoord: the low 24 bits, sign-extended (also keeps wood's squares
// exact in 64 bits).
int64_t solid(int64_t raw) {
  constexpr int kBits = 24;
  const int64_t low = raw & ((int64_t{1} << kBits) - 1);
  return low >= (int64_t{1} << (kBits - 1)) ? low - (int64_t{1} << kBits) : low;
}

uint32_t grey(uint32_t l) { return (l << 16) | (l << 8) | l; }

}  // namespace

void check(const MaterialRegs& r) {
  const auto in_range = [](const char* name, int64_t value, int64_t lo, int64_t hi) {
    check_range("material", name, value, lo, hi);
  };
  in_range("g_t", r.g_t, 0, 0xFFFF);
  in_range("g_v", r.g_v, 0, 0xFFFF);
  in_range("g_r", r.g_r, 0, 0xFFFF);
  in_range("g_w", r.g_w, -0x8000, 0x7FFF);
  in_range("offset", r.offset, -0x8000, 0x7FFF);
  in_range("g_l", r.g_l, 0, 0xFFFF);
  in_range("cutoff", r.cutoff, -0x8000, 0x7FFF);
  in_range("pw", r.pw, 1, 20);
  in_range("ph", r.ph, 1, 20);
  // Mortar on both sides leaves a brick of at least one raw unit.
  in_range("mortar_w", r.mortar_w, 0, (int64_t{1} << (r.pw - 1)) - 1);
  in_range("mortar_h", r.mortar_h, 0, (int64_t{1} << (r.ph - 1)) - 1);
}

uint32_t fire_entry(uint32_t k) {
  const double x = std::exp(-static_cast<double>(k) / (1 << kFireTableFracBits));
  return static_cast<uint32_t>(std::floor(x * (1 << kCoordFracBits) + 0.5));
}

int64_t fire_shape(int64_t v) {
  const int64_t k =
      std::clamp<int64_t>(v >> (kCoordFracBits - kFireTableFracBits), 0, kFireTableEntries - 1);
  return fire_entry(static_cast<uint32_t>(k));
}

bool in_brick(const MaterialRegs& r, int64_t u, int64_t v) {
  const int64_t pw = int64_t{1} << r.pw, ph = int64_t{1} << r.ph;
  const bool even_row = ((v >> r.ph) & 1) == 0;
  const int64_t u_shifted = even_row ? u + pw / 2 : u;
  const int64_t ur = u_shifted & (pw - 1), vr = v & (ph - 1);
  return r.mortar_w < ur && ur < pw - r.mortar_w && r.mortar_h < vr && vr < ph - r.mortar_h;
}

namespace {

// The index value of marble, wood, brick and fire from the sums of the shaped coordinates.
uint32_t index_from_sums(const MaterialRegs& r, int64_t u, int64_t v, int64_t w,
                         const FractalSums& sums) {
  const int64_t t = sums.turbulence, f = sums.fractal_sum;
  switch (r.kind) {
    case MaterialKind::kMarble:
      return static_cast<uint32_t>((((t * r.g_t) >> 14) + ((v * r.g_v) >> 12)) & kIndexMask);
    case MaterialKind::kWood: {
      // u^2 + v^2 < 2^47 for 24-bit coordinates, times g_r < 2^16: exact in unsigned 64 bits.
      const uint64_t rings = static_cast<uint64_t>(u * u + v * v) * r.g_r;
      return static_cast<uint32_t>(
          (static_cast<int64_t>(rings >> 24) + ((w * r.g_w) >> 12) + ((t * r.g_t) >> 14)) &
          kIndexMask);
    }
    case MaterialKind::kBrick:
      return static_cast<uint32_t>(((t * r.g_t) >> 14) & kIndexMask);
    case MaterialKind::kFire:
      return static_cast<uint32_t>(
          std::clamp<int64_t>(((f * r.g_t) >> 14) + r.offset, 0, kIndexMask));
    default:
      return 0;  // the gases fog and cloud have no colour table
  }
}

}  // namespace

Shaped shape(const MaterialRegs& r, int64_t u, int64_t v, int64_t w) {
  u = solid(u);
  v = solid(v);
  w = solid(w);
  if (r.kind == MaterialKind::kCloud) return {2 * u, v, w};
  if (r.kind == MaterialKind::kFire) return {u, fire_shape(v), w};
  return {u, v, w};
}

uint32_t colour(const MaterialRegs& r, const ColourTables& tables, int64_t u, int64_t v, int64_t w,
                const FractalSums& sums) {
  u = solid(u);
  v = solid(v);
  w = solid(w);
  const auto entry = [&](const std::array<uint32_t, kColourEntries>& table) {
    return table[index_from_sums(r, u, v, w, sums) >> 8];
  };
  switch (r.kind) {
    case MaterialKind::kFog: {
      const int64_t f = sums.fractal_sum;
      return grey(level(f < 0 ? -f : f, r.g_l));
    }
    case MaterialKind::kCloud: {
      const uint32_t l = sums.fractal_sum > r.cutoff ? level(sums.fractal_sum, r.g_l) : 0;
      return (l << 16) | (l << 8) | 0xFF;
    }
    case MaterialKind::kBrick:
      return entry(in_brick(r, u, v) ? tables.main : tables.mortar);
    default:
      return entry(tables.main);
  }
}

uint32_t index_value(const NoiseConfig& c, const MaterialRegs& r, int64_t u, int64_t v, int64_t w) {
  const Shaped s = shape(r, u, v, w);
  return index_from_sums(r, solid(u), solid(v), solid(w),
                         port_sums(c, fractal_sums(c, s.u, s.v, s.w)));
}

uint32_t shade_material(const NoiseConfig& c, const MaterialRegs& r, const ColourTables& tables,
                        int64_t u, int64_t v, int64_t w) {
  const Shaped s = shape(r, u, v, w);
  return colour(r, tables, u, v, w, port_sums(c, fractal_sums(c, s.u, s.v, s.w)));
}

}  // namespace tmu::perlin
