// The golden deflection units (golden/deflect/): the normal encoder's divider and angle
// table, its hard cases (zero, tiny, poles, octant boundaries, equal components), the
// spherical-to-spherical map's symmetry and the MBR's hit / miss / bypass sequence, the
// coordinate tables; and every unit's error against the ideal model, with the bounds
// reasoned out next to them. The definitions the two models share (sphere_grid_definition.hpp,
// view_frame_definition.hpp) on their own, and the ideal's own decoding of the grid angles
// equal to golden's.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <iostream>
#include <numbers>
#include <random>

#include "deflect/bump_map.hpp"
#include "deflect/coord_tables.hpp"
#include "deflect/cube_ideal.hpp"
#include "deflect/cube_map.hpp"
#include "deflect/deflect_ideal.hpp"
#include "deflect/normal_encoder.hpp"
#include "deflect/s2s_map.hpp"

namespace tmu::deflect {
namespace {

constexpr double kOne = 16384.0;  // UnitComp SQ2.14
const SphereGrid kGrid;           // 512 x 256
const double kStepDeg = 360.0 / 512;

int16_t comp(double v) { return static_cast<int16_t>(std::lround(v * kOne)); }

double encode_error(const NormalEncoder& enc, glm::dvec3 n) {
  const int16_t x = comp(n.x), y = comp(n.y), z = comp(n.z);
  const SphereAngle a = enc.encode(x, y, z);
  return ideal::angle_deg(ideal::grid_vector(enc.config().grid, a), glm::dvec3(x, y, z));
}

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> nd;
  return glm::normalize(glm::dvec3(nd(rng), nd(rng), nd(rng)));
}

// --- the grid's definition -------------------------------------------------------------

// The grid's sizes and step on their own, for every grid the units allow: 4Q phi nodes, Q
// theta magnitudes, a sign bit above them, 2 pi / 4Q per step; the default is the paper's
// 512 x 256. The default view frame is orthonormal with v_dir = v_side x v_up.
TEST(DeflectGridTest, DefinitionSizesStepAndDefaultView) {
  for (int a = 6; a <= 12; ++a) {
    const SphereGrid g{a};
    EXPECT_EQ(g.phi_count(), 4 * g.quarter());
    EXPECT_EQ(g.quarter(), 1u << g.mag_bits());
    EXPECT_EQ(g.theta_bits(), g.mag_bits() + 1);
    EXPECT_EQ(g.phi_mask() + 1, g.phi_count());
    EXPECT_DOUBLE_EQ(g.step() * g.phi_count(), 2 * std::numbers::pi);
  }
  EXPECT_EQ(kGrid.phi_count(), 512u);
  const ViewFrame f;
  const glm::dvec3 side(f.side[0], f.side[1], f.side[2]), up(f.up[0], f.up[1], f.up[2]),
      dir(f.dir[0], f.dir[1], f.dir[2]);
  EXPECT_EQ(glm::dot(side, up), 0.0);
  EXPECT_EQ(glm::length(side), 1.0);
  EXPECT_EQ(glm::length(up), 1.0);
  EXPECT_EQ(glm::cross(side, up), dir);
}

// Two implementations of the angles' encoding: the ideal's decoding (its own arithmetic) is
// golden's (phi_mask, theta_steps) on every raw value of every grid, bits above the fields
// included, and it inverts golden's make_theta.
TEST(DeflectGridTest, IdealDecodingIsGoldensOnEveryValue) {
  for (int a = 6; a <= 12; ++a) {
    const SphereGrid g{a};
    for (uint32_t x = 0; x < 2 * g.phi_count(); ++x) {
      const ideal::Angles p = ideal::grid_angles(g, SphereAngle{x, 0});
      ASSERT_EQ(p.phi, (x & g.phi_mask()) * g.step()) << a << " phi " << x;
      const ideal::Angles t = ideal::grid_angles(g, SphereAngle{0, x});
      ASSERT_EQ(t.theta, theta_steps(g, x) * g.step()) << a << " theta " << x;
      ASSERT_FALSE(std::signbit(t.theta) && t.theta == 0) << a << " theta " << x << ": -0.0";
    }
    for (uint32_t m = 0; m < g.quarter(); ++m) {
      for (const bool negative : {false, true}) {
        const double theta = ideal::grid_angles(g, {0, make_theta(g, negative, m)}).theta;
        EXPECT_EQ(theta, (negative ? -1.0 : 1.0) * m * g.step());
      }
    }
  }
}

// --- the divider ------------------------------------------------------------------------

// A seed of S bits is within 2^-(S+1) relative of 1/d (half a bucket of 1/m's slope <= 1);
// one Newton-Raphson step squares the relative error: 2^-(2S+2) = 2^-16 for S = 7, one LSB
// of the UQ1.16 ratio. The truncations (r1 and n r1, and n keeping 16 bits of num) add a few
// more: the bound is 5 LSBs of t, over all seed sizes the encoder allows down to S = 7.
TEST(DeflectEncoderTest, DividerWithinFiveLsbOfTheExactRatio) {
  std::mt19937_64 rng(7);
  for (int s : {7, 8, 10}) {
    double worst = 0;
    for (int i = 0; i < 300000; ++i) {
      const uint32_t den = static_cast<uint32_t>(rng() >> (32 + rng() % 32));
      if (den == 0) continue;
      const uint32_t num = static_cast<uint32_t>(rng() % (uint64_t{den} + 1));
      const double exact = std::ldexp(static_cast<double>(num) / den, kRatioFrac);
      worst = std::max(worst, std::fabs(divide_ratio(num, den, s) - exact));
    }
    std::cout << "[ divider S=" << s << " ] max error " << worst << " LSB of 2^-16\n";
    EXPECT_LE(worst, 5.0) << "seed bits " << s;
  }
  EXPECT_EQ(divide_ratio(0, 0, 7), 0u);  // den = 0: t = 0
  // Equal: one LSB short of one or one (the top bucket of the angle table either way).
  EXPECT_GE(divide_ratio(1, 1, 7), (1u << 16) - 1);
  EXPECT_GE(divide_ratio(0xFFFFFFFFu, 0xFFFFFFFFu, 7), (1u << 16) - 1);
  EXPECT_LE(divide_ratio(0xFFFFFFFFu, 0xFFFFFFFFu, 7), 1u << 16);
}

// --- the angle table --------------------------------------------------------------------

// Every index the encoder can form is in the table, entries rise with t and end at 45
// degrees (Q/2 steps); the floating index keeps each bucket's angle span small.
TEST(DeflectEncoderTest, AngleTableIsMonotoneAndCoversZeroTo45Degrees) {
  for (auto [e, m] : {std::pair{4, 5}, {1, 7}, {8, 6}}) {
    EncoderConfig c;
    c.lut_exp = e;
    c.lut_mant = m;
    const auto table = angle_table(c);
    EXPECT_LE(angle_entry(c, angle_index(c, 0)), 5u);  // the encoder bypasses t = 0
    EXPECT_EQ(angle_entry(c, angle_index(c, 1u << 16)), c.grid.quarter() / 2);
    uint32_t last = 0;
    for (uint32_t t = 0; t <= (1u << 16); t += 7) {
      const uint32_t i = angle_index(c, t);
      ASSERT_LT(i, table.size());
      EXPECT_GE(table[i], last) << "t " << t;
      last = table[i];
    }
  }
}

// --- the encoder against the ideal ------------------------------------------------------

// Bound, 512 x 256 grid, E = 4, M = 5: the grid alone is off by up to half a step in each
// angle (0.35 deg, 0.5 deg on the diagonal); the table's widest bucket (t = 1/4 .. 9/32 at
// e = 0: atan sqrt spans 1.43 deg) adds half of it. Measured 1.14 deg max, 0.33 mean over
// 200k random directions; the bound 1.25 deg (1.8 steps) keeps that margin. The paper's
// linear index (E = 1, M = 7) measures 3.9 deg: its first bucket spans 0 .. 5 degrees.
TEST(DeflectEncoderTest, UnitNormalsWithinBoundOfIdeal) {
  NormalEncoder enc{EncoderConfig{}};
  std::mt19937_64 rng(11);
  double worst = 0, sum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double e = encode_error(enc, random_unit(rng));
    worst = std::max(worst, e);
    sum += e;
  }
  std::cout << "[ encoder 512x256 E4 M5 ] max " << worst << " deg, mean " << sum / n << " deg\n";
  EXPECT_LE(worst, 1.25);
  EXPECT_LE(sum / n, 0.4);
}

// The hard cases, each with its stated expectation (normal_encoder.hpp).
TEST(DeflectEncoderTest, HardCases) {
  NormalEncoder enc{EncoderConfig{}};
  const uint32_t q = kGrid.quarter();
  // The zero normal is +z.
  EXPECT_EQ(enc.encode(0, 0, 0), (SphereAngle{0, 0}));
  // Poles: phi undefined (0), theta saturates one step short of 90 degrees.
  EXPECT_EQ(enc.encode(0, 16384, 0), (SphereAngle{0, make_theta(kGrid, false, q - 1)}));
  EXPECT_EQ(enc.encode(0, -16384, 0), (SphereAngle{0, make_theta(kGrid, true, q - 1)}));
  // The axes in the horizontal plane: +z 0, +x 90, -z 180, -x 270 degrees, theta +0.
  EXPECT_EQ(enc.encode(0, 0, 16384), (SphereAngle{0, 0}));
  EXPECT_EQ(enc.encode(16384, 0, 0), (SphereAngle{q, 0}));
  EXPECT_EQ(enc.encode(0, 0, -16384), (SphereAngle{2 * q, 0}));
  EXPECT_EQ(enc.encode(-16384, 0, 0), (SphereAngle{3 * q, 0}));
  // Two equal largest components: exactly 45 degrees, each quadrant.
  EXPECT_EQ(enc.encode(9000, 0, 9000).phi, q / 2);
  EXPECT_EQ(enc.encode(9000, 0, -9000).phi, 3 * q / 2);
  EXPECT_EQ(enc.encode(-9000, 0, -9000).phi, 5 * q / 2);
  EXPECT_EQ(enc.encode(-9000, 0, 9000).phi, 7 * q / 2);
  // y^2 = x^2 + z^2 (3, 4, 5 triangle): theta exactly 45 degrees.
  EXPECT_EQ(enc.encode(3000, 5000, 4000).theta, make_theta(kGrid, false, q / 2));
  // The extremes of the port: -32768 and 32767 (|N| near 2) encode like unit vectors.
  EXPECT_EQ(enc.encode(-32768, 0, 0), enc.encode(-16384, 0, 0));
  EXPECT_EQ(enc.encode(32767, 32767, 32767), enc.encode(9459, 9459, 9459));
  // Length does not matter: a tiny normal encodes like its long multiple, down to 1 LSB.
  EXPECT_EQ(enc.encode(1, 0, 0), (SphereAngle{q, 0}));
  EXPECT_EQ(enc.encode(0, -1, 0), enc.encode(0, -16384, 0));
  EXPECT_EQ(enc.encode(1, 1, 1), enc.encode(9000, 9000, 9000));
  EXPECT_EQ(enc.encode(-3, 4, 5), enc.encode(-3000, 4000, 5000));
  // A zero y: theta is +0 on both sides.
  EXPECT_FALSE(theta_negative(kGrid, enc.encode(100, 0, -50).theta));
}

// Scale invariance over random directions: N and a shorter copy (1/64 of the length, still
// >= 3 significant bits per component) encode within one step of each other; most equal.
TEST(DeflectEncoderTest, ShortNormalsEncodeLikeLongOnes) {
  NormalEncoder enc{EncoderConfig{}};
  std::mt19937_64 rng(12);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 n = random_unit(rng);
    const double e = encode_error(enc, n / 64.0);
    worst = std::max(worst, e);
  }
  std::cout << "[ encoder, |N| = 1/64 ] max " << worst << " deg\n";
  // 8-bit components (1/64 of 2^14): the direction itself is only known to ~0.5 / 256 rad.
  EXPECT_LE(worst, 1.25 + 0.25);
}

// --- the spherical-to-spherical map -----------------------------------------------------

// The flat bump texel (0, +0) returns every (canonical) normal of the grid exactly.
TEST(DeflectMapTest, FlatBumpReturnsTheNormal) {
  S2sMap map(kGrid);
  DeflectionUnit unit(map);
  for (uint32_t p = 0; p < kGrid.phi_count(); ++p) {
    for (uint32_t t = 0; t < 2 * kGrid.quarter(); ++t) {
      const SphereAngle n{p, t};
      if (theta_negative(kGrid, t) && theta_mag(kGrid, t) == 0) continue;  // -0: not canonical
      ASSERT_EQ(unit.deflect(n, SphereAngle{0, 0}).normal, n) << "phi " << p << " theta " << t;
    }
  }
}

// Against the exact rotation R_y(phi_N) R_x(-theta_N) D of the same grid angles: only the
// map's output rounding (half a step in each angle: 0.5 deg on the diagonal) and the
// saturation at the poles (one step) remain. Measured 0.703 deg max (= one step, at the
// pole), 0.24 mean; bound one step.
TEST(DeflectMapTest, DeflectionWithinOneStepOfIdeal) {
  S2sMap map(kGrid);
  DeflectionUnit unit(map);
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<uint32_t> phi(0, kGrid.phi_mask()), mag(0, kGrid.quarter() - 1);
  double worst = 0, sum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const SphereAngle normal{phi(rng), make_theta(kGrid, rng() & 1, mag(rng))};
    const SphereAngle bump{phi(rng), make_theta(kGrid, rng() & 1, mag(rng))};
    const glm::dvec3 exact =
        ideal::deflect(ideal::grid_angles(kGrid, normal), ideal::grid_angles(kGrid, bump));
    const double e =
        ideal::angle_deg(ideal::grid_vector(kGrid, unit.deflect(normal, bump).normal), exact);
    worst = std::max(worst, e);
    sum += e;
  }
  std::cout << "[ deflection 512x256 ] max " << worst << " deg, mean " << sum / n << " deg\n";
  EXPECT_LE(worst, kStepDeg + 1e-9);
  EXPECT_LE(sum / n, 0.3);
}

// Hard cases of the rotation: theta_N at the poles with large deflections, phi wrapping
// across 0 / 2 pi after each offset, theta' on both sides: the result stays on the grid and
// within one step of the exact rotation (theta can never leave [-90, 90]: it comes from
// the map).
TEST(DeflectMapTest, HardCasesStayWithinOneStep) {
  S2sMap map(kGrid);
  DeflectionUnit unit(map);
  const uint32_t q = kGrid.quarter(), top = q - 1;
  const std::vector<std::pair<SphereAngle, SphereAngle>> cases = {
      {{0, make_theta(kGrid, false, top)}, {0, make_theta(kGrid, false, top)}},  // poles
      {{0, make_theta(kGrid, true, top)}, {100, make_theta(kGrid, true, top)}},
      {{511, make_theta(kGrid, false, 5)}, {3, make_theta(kGrid, false, 0)}},      // + phi_N wraps
      {{7, make_theta(kGrid, false, 20)}, {0, make_theta(kGrid, false, 10)}},      // phi' < 0
      {{200, make_theta(kGrid, true, 20)}, {500, make_theta(kGrid, true, 30)}},    // phi' > 2 pi
      {{50, make_theta(kGrid, false, 0)}, {q, make_theta(kGrid, false, 0)}},       // bypass, pole
      {{50, make_theta(kGrid, false, 0)}, {3 * q, make_theta(kGrid, true, 40)}},   // bypass
      {{50, make_theta(kGrid, false, 0)}, {2 * q, make_theta(kGrid, false, 40)}},  // y = 0
  };
  for (const auto& [normal, bump] : cases) {
    const glm::dvec3 exact =
        ideal::deflect(ideal::grid_angles(kGrid, normal), ideal::grid_angles(kGrid, bump));
    const Deflected d = unit.deflect(normal, bump);
    EXPECT_LE(ideal::angle_deg(ideal::grid_vector(kGrid, d.normal), exact), kStepDeg + 1e-9)
        << "normal " << normal.phi << "," << normal.theta << " bump " << bump.phi << ","
        << bump.theta;
  }
}

// The bypass column (k = Q) is exact in closed form and leaves the MBR alone; blocks are
// fetched once and hit after.
TEST(DeflectMapTest, MbrHitMissBypassSequence) {
  S2sMap map(kGrid);
  DeflectionUnit unit(map);
  const uint32_t q = kGrid.quarter();
  const SphereAngle n{0, 0};
  EXPECT_EQ(unit.deflect(n, {1, 1}).access, MapAccess::kMiss);    // empty after reset
  EXPECT_EQ(unit.deflect(n, {2, 2}).access, MapAccess::kHit);     // same 4x4 block
  EXPECT_EQ(unit.deflect(n, {q, 2}).access, MapAccess::kBypass);  // z = 0: no look-up
  EXPECT_EQ(unit.deflect(n, {3, 3}).access, MapAccess::kHit);     // the MBR kept its block
  EXPECT_EQ(unit.deflect(n, {4, 3}).access, MapAccess::kMiss);    // next block over
  EXPECT_EQ(unit.deflect(n, {3, 3}).access, MapAccess::kMiss);    // and back
  // Symmetric inputs share the first-octant block: phi' -> -phi' is the same entry.
  EXPECT_EQ(unit.deflect(n, {kGrid.phi_count() - 3, 3}).access, MapAccess::kHit);
  unit.reset();
  EXPECT_EQ(unit.deflect(n, {3, 3}).access, MapAccess::kMiss);
}

// Every input octant reduces to first-octant (k, k_theta) and expands back: the looked-up
// direction (before + phi_N) is within one step of the exact x-polar to y-polar conversion.
TEST(DeflectMapTest, OctantSymmetryMatchesTheExactConversion) {
  S2sMap map(kGrid);
  DeflectionUnit unit(map);
  double worst = 0;
  for (uint32_t p = 0; p < kGrid.phi_count(); p += 3) {
    for (uint32_t t = 0; t < 2 * kGrid.quarter(); t += 5) {
      const SphereAngle bump{p, t};
      const glm::dvec3 exact = ideal::bump_vector(ideal::grid_angles(kGrid, bump));
      const SphereAngle got = unit.deflect(SphereAngle{0, 0}, bump).normal;
      worst = std::max(worst, ideal::angle_deg(ideal::grid_vector(kGrid, got), exact));
    }
  }
  EXPECT_LE(worst, kStepDeg + 1e-9);
}

// --- the coordinate tables --------------------------------------------------------------

ViewFrame tilted_view() {
  const glm::dvec3 side = glm::normalize(glm::dvec3(1, 0.3, -0.2));
  const glm::dvec3 up = glm::normalize(glm::cross(glm::dvec3(0.1, 0.2, 1), side));
  const glm::dvec3 dir = glm::cross(side, up);
  return {{side.x, side.y, side.z}, {up.x, up.y, up.z}, {dir.x, dir.y, dir.z}};
}

// Against the exact dot products of the same grid normal. W = 10: each entry is off by at
// most half an LSB (2^-10) and the products add the two entries' errors: |uN error| <=
// 1.5 2^-9 + 2^-15 = 0.0030 in theory; measured 0.0033 for uN (the saturated cos(0) =
// 1 - 2^-9 adds 2^-9 at theta = 0), so the bound is 2^-9 * 2 = 0.0039. uR = 2 hN uN doubles
// both errors (0.0078), wR = 2 hN^2 - 1 quadruples hN's (0.0156); measured 0.0072, 0.0129.
TEST(DeflectCoordTest, CoordinatesWithinBoundOfIdeal) {
  const ViewFrame view = tilted_view();
  CoordTables tables(TableConfig{}, view);
  double e[5] = {0, 0, 0, 0, 0};
  for (uint32_t p = 0; p < kGrid.phi_count(); ++p) {
    for (uint32_t t = 0; t < 2 * kGrid.quarter(); ++t) {
      const SphereAngle n{p, t};
      const MapCoords g = tables.eval(n);
      const ideal::Coords x = ideal::map_coords(view, ideal::grid_vector(kGrid, n));
      const double d[5] = {g.un / kOne - x.un, g.vn / kOne - x.vn, g.ur / kOne - x.ur,
                           g.vr / kOne - x.vr, g.wr / kOne - x.wr};
      for (int k = 0; k < 5; ++k) e[k] = std::max(e[k], std::fabs(d[k]));
    }
  }
  std::cout << "[ coord tables W=10 ] max error uN " << e[0] << " vN " << e[1] << " uR " << e[2]
            << " vR " << e[3] << " wR " << e[4] << "\n";
  EXPECT_LE(e[0], 0.0039);
  EXPECT_LE(e[1], 0.0039);
  EXPECT_LE(e[2], 0.0078);
  EXPECT_LE(e[3], 0.0078);
  EXPECT_LE(e[4], 0.0156);
}

// Symmetries: phi + pi negates the phi tables' terms, -theta the odd theta tables' (exact in
// the tables; the rounded outputs keep them to an LSB or four).
TEST(DeflectCoordTest, SymmetriesHoldToTheRounding) {
  CoordTables tables(TableConfig{}, tilted_view());
  const uint32_t q = kGrid.quarter();
  for (uint32_t p = 0; p < 2 * q; p += 7) {
    for (uint32_t m = 0; m < q; m += 9) {
      const MapCoords a = tables.eval({p, make_theta(kGrid, false, m)});
      const MapCoords b = tables.eval({p + 2 * q, make_theta(kGrid, true, m)});
      // (phi + pi, -theta) is the antipode: uN, vN negate within one LSB (rounding half up
      // is not odd-symmetric); uR and wR keep, within the 2 (1 + 1) = 4 LSBs that one LSB
      // in each of hN and uN makes of 2 hN uN.
      EXPECT_LE(std::abs(a.un + b.un), 1);
      EXPECT_LE(std::abs(a.vn + b.vn), 1);
      EXPECT_LE(std::abs(a.ur - b.ur), 4);
      EXPECT_LE(std::abs(a.wr - b.wr), 4);
    }
  }
  // Table entries never reach -2^(W-1): negation cannot overflow.
  for (const TableWrite& w : tables.writes()) EXPECT_GT(w.value, -(1 << 9));
}

// --- the bump-map tool ------------------------------------------------------------------

// A flat height map gives the flat texel everywhere; a ramp along u tilts D away from u
// (theta_D = -atan(slope), phi_D = 0), one along v tilts it in the v-w plane (theta_D = 0,
// phi_D = atan(slope): D_v = -sin phi_D); the packing round-trips every texel of the grid.
TEST(DeflectBumpMapTest, FlatRampsAndPacking) {
  ImageRgb8 flat(8, 8);
  for (Rgb8& p : flat.pixels) p = {128, 128, 128};
  for (const Rgb8& t : bump_map_from_heights(flat, 4.0, kGrid).pixels) {
    EXPECT_EQ(unpack_bump(kGrid, t), (SphereAngle{0, 0}));
  }
  const double slope = 0.5, deg = std::atan(slope) * 180 / 3.14159265358979323846;
  const auto steps = static_cast<uint32_t>(std::lround(deg / kStepDeg));
  EXPECT_EQ(bump_texel(kGrid, slope, 0), (SphereAngle{0, make_theta(kGrid, true, steps)}));
  EXPECT_EQ(bump_texel(kGrid, 0, slope), (SphereAngle{steps, 0}));
  EXPECT_EQ(bump_texel(kGrid, 0, -slope), (SphereAngle{kGrid.phi_count() - steps, 0}));
  for (uint32_t p = 0; p < kGrid.phi_count(); ++p) {
    for (uint32_t t = 0; t < 2 * kGrid.quarter(); ++t) {
      if (theta_negative(kGrid, t) && theta_mag(kGrid, t) == 0) continue;
      ASSERT_EQ(unpack_bump(kGrid, pack_bump(kGrid, {p, t})), (SphereAngle{p, t}));
    }
  }
}

// --- the cube map's addressing ------------------------------------------------------------

// Hard cases, each with its stated expectation (cube_map.hpp), on a 256-texel face: the axes
// hit the face centres; a cube edge (two equal largest components) belongs to the earlier
// axis and lands on that face's border; a corner (three equal) on the +X face's corner; the
// zero vector at +X's centre.
TEST(DeflectCubeMapTest, AxesEdgesCornersAndZero) {
  constexpr int32_t one = 16384, centre = 128 * 256;
  for (uint32_t face = 0; face < 6; ++face) {
    int32_t r[3] = {0, 0, 0};
    r[face / 2] = face % 2 ? -one : one;
    const CubeAddress a = cube_address(r[0], r[1], r[2], 8);
    EXPECT_EQ(a.face, face);
    EXPECT_EQ(a.u, centre);
    EXPECT_EQ(a.v, centre);
  }
  // +X / +Y edge: +X wins; tc = -y = -ma: the face's top border (v = 0 within the divider's
  // last LSB), sc = -z = 0: the middle.
  const CubeAddress edge = cube_address(11585, 11585, 0, 8);
  EXPECT_EQ(edge.face, 0u);
  EXPECT_EQ(edge.u, centre);
  EXPECT_LE(edge.v, 1);
  // -Y / -Z edge: -Y wins (y before z); tc = -z = +ma: the bottom border.
  const CubeAddress edge2 = cube_address(0, -11585, -11585, 8);
  EXPECT_EQ(edge2.face, 3u);
  EXPECT_GE(edge2.v, 256 * 256 - 1);
  // The (+, +, +) corner: +X, sc = -z = -ma, tc = -y = -ma: the face's (0, 0) corner.
  const CubeAddress corner = cube_address(9459, 9459, 9459, 8);
  EXPECT_EQ(corner.face, 0u);
  EXPECT_LE(corner.u, 1);
  EXPECT_LE(corner.v, 1);
  const CubeAddress zero = cube_address(0, 0, 0, 8);
  EXPECT_EQ(zero.face, 0u);
  EXPECT_EQ(zero.u, centre);
  EXPECT_EQ(zero.v, centre);
}

// Against the exact division: the same face always (both decide on the same integers), and
// the coordinate within the divider's 4 LSB of 2^-16, halved, plus the truncation of r / 2
// (one LSB of 2^-16) and the rounding to 1/256 texel: (3 2^-16) 2^L + 2^-9 = 0.0137 texels at
// L = 8; bound 0.015. Measured max printed.
TEST(DeflectCubeMapTest, WithinBoundOfIdeal) {
  std::mt19937_64 rng(21);
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const glm::dvec3 d = random_unit(rng) * (i % 2 ? 1.0 : 1.9);
    const int32_t x = comp(d.x), y = comp(d.y), z = comp(d.z);
    const CubeAddress g = cube_address(x, y, z, 8);
    const CubeIdeal e = cube_address_ideal(x, y, z, 8);
    ASSERT_EQ(g.face, e.face);
    worst = std::max({worst, std::fabs(g.u / 256.0 - e.u), std::fabs(g.v / 256.0 - e.v)});
  }
  std::cout << "[ cube map, 256-texel faces ] max error " << worst << " texels\n";
  EXPECT_LE(worst, 0.015);
}

}  // namespace
}  // namespace tmu::deflect
