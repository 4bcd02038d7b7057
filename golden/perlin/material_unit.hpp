// The material unit as the hardware sees it (002 §4.2, Figs. 4.7-4.19): a register file and
// two colour tables behind a write port, and per sample the three stages
//   shape   (u, v, w) -> the fractal unit's coordinates: cloud (2u, v, w), fire (u, e^-v, w),
//           the others unchanged;
//   fractal the fractal sum and the turbulence of the shaped coordinates (noise.hpp);
//   colour  the index and table look-up, the brick test, or the gases' levels (materials.hpp)
// so that colour(u, v, w, fractal_sums(shape(u, v, w))) = shade_material(u, v, w). Writes
// apply in order: a sample sees every write before it. This file is the specification the
// hls and rtl models match.
//
// Register writes (MaterialReg, 16-bit values, two's complement for the signed registers):
// kind 0..5 (MaterialKind), g_t, g_v, g_r, g_w, offset, g_l, cutoff, pw, ph, mortar_w,
// mortar_h as in MaterialRegs. A value outside a register's range is stored as its nearest
// limit (a port cannot reject a write): kind saturates at 5 (fire), pw and ph at 1..20, a
// mortar at half its period minus one (also when pw or ph shrink); an unknown register is
// ignored. Table writes: bit 0 of the table selects main (0) or mortar (1); an index beyond
// 127 is ignored; the low 24 bits are RGB888.
#pragma once

#include <array>
#include <cstdint>

#include "perlin/materials.hpp"

namespace tmu::perlin {

enum class MaterialReg : uint8_t {
  kKind,
  kGt,
  kGv,
  kGr,
  kGw,
  kOffset,
  kGl,
  kCutoff,
  kPw,
  kPh,
  kMortarW,
  kMortarH,
  kCount
};

struct Shaped {
  int64_t u = 0, v = 0, w = 0;
};
Shaped shape(const MaterialRegs& regs, int64_t u, int64_t v, int64_t w);
// The colour stage, given the sums of the shaped coordinates.
uint32_t colour(const MaterialRegs& regs, const ColourTables& tables, int64_t u, int64_t v,
                int64_t w, const FractalSums& sums);

class MaterialUnit {
 public:
  explicit MaterialUnit(const NoiseConfig& config = {}) : config_(config) {}
  void write_reg(MaterialReg reg, uint32_t value);  // the low 16 bits
  void write_table(uint32_t table, uint32_t index, uint32_t rgb);
  uint32_t sample(int64_t u, int64_t v, int64_t w) const;  // RGB888
  const MaterialRegs& regs() const { return regs_; }
  const ColourTables& tables() const { return tables_; }

 private:
  NoiseConfig config_;
  MaterialRegs regs_;
  ColourTables tables_;
};

}  // namespace tmu::perlin
