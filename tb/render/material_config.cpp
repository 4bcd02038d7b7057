#include "render/material_config.hpp"

#include <algorithm>
#include <cmath>

#include "perlin/colour_table.hpp"

namespace tmu::render {
namespace {

int32_t fixed(double value, double one, int64_t lo, int64_t hi) {
  return static_cast<int32_t>(std::clamp<int64_t>(std::llround(value * one), lo, hi));
}

}  // namespace

perlin::MaterialRegs material_registers(const host::Procedural& p) {
  perlin::MaterialRegs r;
  r.kind = p.kind;
  r.g_t = static_cast<uint32_t>(fixed(p.turbulence, 256, 0, 0xFFFF));
  r.g_v = static_cast<uint32_t>(fixed(p.stripes, 256, 0, 0xFFFF));
  r.g_r = static_cast<uint32_t>(fixed(p.rings, 256, 0, 0xFFFF));
  r.g_w = fixed(p.slope, 256, -0x8000, 0x7FFF);
  r.offset = fixed(p.offset, 256, -0x8000, 0x7FFF);
  r.g_l = static_cast<uint32_t>(fixed(p.gain, 256, 0, 0xFFFF));
  r.cutoff = fixed(p.cutoff, 16384, -0x8000, 0x7FFF);
  // Periods are powers of two in solid units: 2^pw raw units (SolidCoord has 12 fraction bits).
  r.pw = std::ilogb(p.brick.x) + perlin::kCoordFracBits;
  r.ph = std::ilogb(p.brick.y) + perlin::kCoordFracBits;
  r.mortar_w = std::min(fixed(p.mortar.x, 4096, 0, 0xFFFF), (1 << (r.pw - 1)) - 1);
  r.mortar_h = std::min(fixed(p.mortar.y, 4096, 0, 0xFFFF), (1 << (r.ph - 1)) - 1);
  return r;
}

perlin::ColourTables material_tables(const host::Procedural& p) {
  perlin::ColourTables t;
  if (!p.colours.empty()) t.main = perlin::colour_table(p.colours);
  if (!p.mortar_colours.empty()) t.mortar = perlin::colour_table(p.mortar_colours);
  return t;
}

}  // namespace tmu::render
