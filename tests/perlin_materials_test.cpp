// The six materials' golden model (golden/perlin/materials.hpp): fire's shaping table at
// v = 0 and beyond it, the mod-128 colour index at the wrap (also for negative coordinates),
// brick geometry (joints, the half-brick shift, strict bounds), the gases' rules, coordinates
// beyond SolidCoord, the registers' ranges, and the colour index within a stated bound of the
// ideal model's. The definitions the two models share (material_definition.hpp) on their own,
// and the ideal's own brick test against golden's: equal on SolidCoord's grid, and between
// grid points different only in the raw unit at a joint's lower edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "perlin/material_unit.hpp"
#include "perlin/materials.hpp"
#include "perlin/materials_ideal.hpp"

namespace tmu::perlin {
namespace {

constexpr int64_t kOne = int64_t{1} << kCoordFracBits;

ColourTables ramp_tables() {
  ColourTables t;
  for (uint32_t i = 0; i < kColourEntries; ++i) {
    t.main[i] = (2 * i) << 16 | (255 - 2 * i) << 8 | i;
    t.mortar[i] = 0x808080 + i;
  }
  return t;
}

TEST(PerlinMaterialsTest, FireShapingAtZeroAndBeyondItsTable) {
  EXPECT_EQ(fire_entry(0), 4096u);
  for (uint32_t k = 1; k < kFireTableEntries; ++k) EXPECT_LE(fire_entry(k), fire_entry(k - 1));
  EXPECT_EQ(fire_entry(kFireTableEntries - 1), 0u);  // e^-15.97 rounds to 0 at 12 bits
  EXPECT_EQ(fire_shape(0), 4096);                    // the flame's base: e^0
  EXPECT_EQ(fire_shape(-5 * kOne), 4096);            // below the base: clamped to e^0
  EXPECT_EQ(fire_shape(kOne), 1507);                 // round(e^-1 4096)
  EXPECT_EQ(fire_shape(16 * kOne), 0);               // beyond the table: its last entry
  EXPECT_EQ(fire_shape(int64_t{1} << 40), 0);
}

// Marble with g_t = 0 and one entry per unit of v: the index is floor(v) mod 128, so it wraps
// from 127 to 0 at v = 128 and from 0 to 127 just below v = 0.
TEST(PerlinMaterialsTest, ColourIndexWrapsModulo128) {
  MaterialRegs r;
  r.kind = MaterialKind::kMarble;
  r.g_t = 0;
  r.g_v = 1 << 8;
  const NoiseConfig c;
  const auto entry = [&](int64_t v) { return index_value(c, r, 0, v, 0) >> 8; };
  EXPECT_EQ(entry(128 * kOne - 1), 127u);
  EXPECT_EQ(entry(128 * kOne), 0u);
  EXPECT_EQ(entry(-1), 127u);
  EXPECT_EQ(entry(0), 0u);
  EXPECT_EQ(entry(-128 * kOne), 0u);
  EXPECT_EQ(entry(5 * kOne + kOne / 2), 5u);
  // The table is read at that entry.
  const ColourTables t = ramp_tables();
  EXPECT_EQ(shade_material(c, r, t, 0, -1, 0), t.main[127]);
}

// Coordinates are SolidCoord: the low 24 bits, sign-extended. Wood's squares at the extremes
// stay exact (no overflow), and a coordinate 2^24 raw units away reads the same colour.
TEST(PerlinMaterialsTest, CoordinatesBeyondSolidCoordWrapWithoutOverflow) {
  const NoiseConfig c;
  const ColourTables t = ramp_tables();
  for (MaterialKind k : {MaterialKind::kMarble, MaterialKind::kWood, MaterialKind::kBrick,
                         MaterialKind::kFog, MaterialKind::kCloud, MaterialKind::kFire}) {
    MaterialRegs r;
    r.kind = k;
    r.g_r = 0xFFFF;
    for (int64_t u : {-(int64_t{1} << 23), (int64_t{1} << 23) - 1, int64_t{12345}}) {
      const uint32_t a = shade_material(c, r, t, u, u, -u);
      EXPECT_EQ(shade_material(c, r, t, u + (int64_t{1} << 24), u - (int64_t{5} << 24), -u), a);
    }
  }
}

// Periods of one unit (pw = 12) by half a unit (ph = 11), joints 205 raw units wide.
TEST(PerlinMaterialsTest, BrickJointsAndTheHalfBrickShift) {
  MaterialRegs r;
  r.kind = MaterialKind::kBrick;
  const int64_t mid_row0 = 1024, mid_row1 = 2048 + 1024;  // v in the middle of rows 0 and 1
  // Row 0 is even: shifted by half a brick, so u = 0 is mid-brick and u = 1/2 a joint.
  EXPECT_TRUE(in_brick(r, 0, mid_row0));
  EXPECT_FALSE(in_brick(r, 2048, mid_row0));
  // Row 1 is odd: not shifted.
  EXPECT_FALSE(in_brick(r, 0, mid_row1));
  EXPECT_TRUE(in_brick(r, 2048, mid_row1));
  // Strict bounds: exactly M_W into the period is mortar, one unit more is brick.
  EXPECT_FALSE(in_brick(r, r.mortar_w, mid_row1));
  EXPECT_TRUE(in_brick(r, r.mortar_w + 1, mid_row1));
  EXPECT_FALSE(in_brick(r, 4096 - r.mortar_w, mid_row1));
  EXPECT_TRUE(in_brick(r, 4096 - r.mortar_w - 1, mid_row1));
  // Horizontal joints.
  EXPECT_FALSE(in_brick(r, 2048, 2048 + r.mortar_h));
  EXPECT_TRUE(in_brick(r, 2048, 2048 + r.mortar_h + 1));
  // Negative rows follow the same pattern (row -1 is odd, row -2 even).
  EXPECT_EQ(in_brick(r, 2048, mid_row1 - 4096), in_brick(r, 2048, mid_row1));
  EXPECT_EQ(in_brick(r, 0, mid_row0 - 4096), in_brick(r, 0, mid_row0));
  // The colour comes from the brick table in a brick, the mortar table in a joint.
  const ColourTables t = ramp_tables();
  const NoiseConfig c;
  const uint32_t i = index_value(c, r, 2048, mid_row0, 0) >> 8;
  EXPECT_EQ(shade_material(c, r, t, 2048, mid_row0, 0), t.mortar[i]);
  const uint32_t j = index_value(c, r, 0, mid_row0, 0) >> 8;
  EXPECT_EQ(shade_material(c, r, t, 0, mid_row0, 0), t.main[j]);
}

// The registers' defaults are in range, and the index's entry bits (14:8) address every
// colour table entry and no more.
TEST(PerlinMaterialsTest, DefinitionsDefaultsAndTableSize) {
  EXPECT_NO_THROW(check(MaterialRegs{}));
  EXPECT_EQ(kColourEntries, 1 << (kIndexBits - 8));
  const ColourTables t;
  EXPECT_EQ(t.main.size(), size_t{kColourEntries});
  EXPECT_EQ(t.mortar.size(), size_t{kColourEntries});
}

// Brick registers to try: the default, small periods (joints dominate), no mortar, the widest
// mortar check() allows, and a tall period.
std::vector<MaterialRegs> brick_registers() {
  std::vector<MaterialRegs> out;
  constexpr std::array<std::array<int, 4>, 5> kCases = {
      {{12, 11, 205, 205}, {3, 2, 1, 0}, {5, 4, 0, 0}, {4, 6, 7, 31}, {16, 9, 300, 17}}};
  for (const auto& [pw, ph, mw, mh] : kCases) {
    MaterialRegs r;
    r.kind = MaterialKind::kBrick;
    r.pw = pw;
    r.ph = ph;
    r.mortar_w = mw;
    r.mortar_h = mh;
    check(r);
    out.push_back(r);
  }
  return out;
}

// Two implementations of the brick geometry: the ideal's (exact coordinates) is golden's at
// every point of SolidCoord's grid, through every cell of small periods (rows -3..3, including
// every joint edge) and at random points far out.
TEST(PerlinMaterialsTest, IdealBrickTestIsGoldensOnTheGrid) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int64_t> any(-(int64_t{1} << 23), (int64_t{1} << 23) - 1);
  for (const MaterialRegs& r : brick_registers()) {
    const int64_t pw = int64_t{1} << r.pw, ph = int64_t{1} << r.ph;
    const auto same = [&](int64_t u, int64_t v) {
      return ideal::in_brick(r, double(u) / kOne, double(v) / kOne) == in_brick(r, u, v);
    };
    if (r.pw <= 6 && r.ph <= 6) {
      for (int64_t v = -3 * ph; v < 3 * ph; ++v) {
        for (int64_t u = -2 * pw; u < 2 * pw; ++u) ASSERT_TRUE(same(u, v)) << u << " " << v;
      }
    }
    for (int n = 0; n < 100000; ++n) {
      const int64_t u = any(rng), v = any(rng);
      ASSERT_TRUE(same(u, v)) << u << " " << v;
    }
  }
}

// Between grid points golden sees the coordinate floored to the grid: a point in the raw unit
// just past a joint's lower edge (M_W < u_r < M_W + 1 raw units) is brick to the ideal and
// mortar to golden. That is the only difference (the upper edges agree: u_r < W + M_W and its
// floor are the same test).
TEST(PerlinMaterialsTest, IdealBrickTestOffTheGridDiffersOnlyPastALowerEdge) {
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> any(-64, 64);
  for (const MaterialRegs& r : brick_registers()) {
    const int64_t pw = int64_t{1} << r.pw, ph = int64_t{1} << r.ph;
    int differ = 0;
    constexpr int kSamples = 200000;
    for (int n = 0; n < kSamples; ++n) {
      const double u = any(rng), v = any(rng);
      const auto ru = static_cast<int64_t>(std::floor(u * kOne)),
                 rv = static_cast<int64_t>(std::floor(v * kOne));
      const bool golden = in_brick(r, ru, rv);
      if (ideal::in_brick(r, u, v) == golden) continue;
      ++differ;
      ASSERT_FALSE(golden) << u << " " << v;
      const bool even_row = ((rv >> r.ph) & 1) == 0;
      const int64_t ur = (even_row ? ru + pw / 2 : ru) & (pw - 1), vr = rv & (ph - 1);
      EXPECT_TRUE(ur == r.mortar_w || vr == r.mortar_h) << u << " " << v;
    }
    std::cout << "brick pw " << r.pw << " ph " << r.ph << ": ideal and golden differ on "
              << 100.0 * differ / kSamples << " % of off-grid points\n";
  }
}

TEST(PerlinMaterialsTest, GasRules) {
  const NoiseConfig c;
  const ColourTables t = ramp_tables();
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<int64_t> any(-(int64_t{1} << 23), (int64_t{1} << 23) - 1);
  MaterialRegs fog, cloud, closed;
  fog.kind = MaterialKind::kFog;
  cloud.kind = MaterialKind::kCloud;
  closed.kind = MaterialKind::kCloud;
  closed.cutoff = 0x7FFF;  // above any fractal sum: clear sky
  for (int n = 0; n < 2000; ++n) {
    const int64_t u = any(rng), v = any(rng), w = any(rng);
    const uint32_t g = shade_material(c, fog, t, u, v, w);
    EXPECT_EQ(g >> 16, g & 0xFF);  // grey
    EXPECT_EQ((g >> 8) & 0xFF, g & 0xFF);
    const int32_t f = fractal_sums(c, u, v, w).fractal_sum;
    EXPECT_EQ(g & 0xFF, std::min<int64_t>(255, (int64_t{std::abs(f)} * fog.g_l) >> 22));
    const uint32_t s = shade_material(c, cloud, t, u, v, w);
    EXPECT_EQ(s & 0xFF, 0xFFu);  // the sky's blue
    EXPECT_EQ(s >> 16, (s >> 8) & 0xFF);
    if (fractal_sums(c, 2 * u, v, w).fractal_sum <= cloud.cutoff) {
      EXPECT_EQ(s >> 8, 0u);
    }
    EXPECT_EQ(shade_material(c, closed, t, u, v, w), 0xFFu);
  }
}

TEST(PerlinMaterialsTest, RegistersOutOfRangeAreNamed) {
  MaterialRegs r;
  EXPECT_NO_THROW(check(r));
  r.mortar_w = 2048;  // half the period: no brick left
  EXPECT_THROW(check(r), std::invalid_argument);
  r = MaterialRegs{};
  r.g_w = 0x8000;
  try {
    check(r);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("g_w"), std::string::npos);
  }
}

// The colour index against the ideal's: the sums are within 0.089 of the ideal (the bound of
// tests/perlin_test.cpp at the default widths), so g_t times that, plus the floors of the other
// terms (below 1/256 entry each), bounds how far the index moves: ceil(32 x 0.089 + 0.01) = 3
// entries at g_t = 32. Fire adds its shaping table: e^-v read at v floored to 1/32 is off by
// at most 1 - e^(-1/32) + 2^-13 = 0.0309 units of v_g; the noise changes by at most 3 per unit
// (sm' <= 1.5 times |b - a| <= 2), each octave 2^i as fast at 2^-i the amplitude: the sum by
// at most 4 x 3 x 0.0309 = 0.37, 11.9 entries more at g_t = 32.
// Measured: at most 1 entry (fire 3), on about 8 % of the samples.
TEST(PerlinMaterialsTest, ColourIndexWithinTheBoundOfTheIdeal) {
  const NoiseConfig c;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> any(-64, 64);
  for (MaterialKind k :
       {MaterialKind::kMarble, MaterialKind::kWood, MaterialKind::kBrick, MaterialKind::kFire}) {
    MaterialRegs r;
    r.kind = k;
    r.offset = 64 << 8;
    const double gt = r.g_t / 256.0;
    const double shaping = k == MaterialKind::kFire ? 4 * 3 * 0.0309 : 0.0;
    const int bound = static_cast<int>(std::ceil(gt * (0.0893 + shaping) + 0.01));
    int worst = 0, moved = 0;
    constexpr int kSamples = 20000;
    for (int n = 0; n < kSamples; ++n) {
      // On the raw grid, so that both models see the same coordinates.
      const int64_t u = std::llround(any(rng) * kOne), v = std::llround(any(rng) / 8 * kOne),
                    w = std::llround(any(rng) * kOne);
      const int golden = static_cast<int>(index_value(c, r, u, v, w) >> 8);
      const double x = std::floor(
          ideal::material_index(r, double(u) / kOne, double(v) / kOne, double(w) / kOne));
      const int ideal = k == MaterialKind::kFire
                            ? static_cast<int>(std::clamp(x, 0.0, 127.0))
                            : static_cast<int>(((static_cast<int64_t>(x) % 128) + 128) % 128);
      int d = std::abs(golden - ideal);
      if (k != MaterialKind::kFire) d = std::min(d, 128 - d);  // around the wrap
      worst = std::max(worst, d);
      moved += d != 0;
    }
    std::cout << "material " << int(k) << ": index off by at most " << worst << " entries, "
              << 100.0 * moved / kSamples << " % of samples moved (bound " << bound << ")\n";
    EXPECT_LE(worst, bound);
  }
}

// The unit's write port: registers as MaterialRegs, out-of-range values at their limits,
// unknown registers and table indices beyond 127 ignored; a sample is shade_material of what
// was written, and the three stages compose to it.
TEST(PerlinMaterialsTest, UnitWritePortAndStages) {
  MaterialUnit unit;
  unit.write_reg(MaterialReg::kKind, 9);
  EXPECT_EQ(unit.regs().kind, MaterialKind::kFire);  // saturates at the last kind
  unit.write_reg(MaterialReg::kKind, 2);
  unit.write_reg(MaterialReg::kGw, 0xFFFF);
  EXPECT_EQ(unit.regs().g_w, -1);  // two's complement
  unit.write_reg(MaterialReg::kPw, 40);
  EXPECT_EQ(unit.regs().pw, 20);
  unit.write_reg(MaterialReg::kMortarH, 0xFFFF);
  EXPECT_EQ(unit.regs().mortar_h, (1 << (unit.regs().ph - 1)) - 1);
  unit.write_reg(MaterialReg::kPh, 3);  // the mortar follows a shrinking period
  EXPECT_EQ(unit.regs().mortar_h, 3);
  const MaterialRegs before = unit.regs();
  unit.write_reg(static_cast<MaterialReg>(200), 5);
  EXPECT_EQ(unit.regs(), before);
  unit.write_table(0, 7, 0x12345678);
  unit.write_table(1, 7, 0xABCDEF);
  unit.write_table(0, 128, 0x111111);
  EXPECT_EQ(unit.tables().main[7], 0x345678u);
  EXPECT_EQ(unit.tables().mortar[7], 0xABCDEFu);
  EXPECT_EQ(unit.tables().main[0], 0u);

  const NoiseConfig c;
  const ColourTables t = ramp_tables();
  for (uint32_t i = 0; i < kColourEntries; ++i) {
    unit.write_table(0, i, t.main[i]);
    unit.write_table(1, i, t.mortar[i]);
  }
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<int64_t> any(-(int64_t{1} << 23), (int64_t{1} << 23) - 1);
  for (uint32_t kind = 0; kind < 6; ++kind) {
    unit.write_reg(MaterialReg::kKind, kind);
    for (int n = 0; n < 500; ++n) {
      const int64_t u = any(rng), v = any(rng), w = any(rng);
      const uint32_t got = unit.sample(u, v, w);
      EXPECT_EQ(got, shade_material(c, unit.regs(), unit.tables(), u, v, w));
      const Shaped s = shape(unit.regs(), u, v, w);
      EXPECT_EQ(got, colour(unit.regs(), unit.tables(), u, v, w, fractal_sums(c, s.u, s.v, s.w)));
    }
  }
}

}  // namespace
}  // namespace tmu::perlin
