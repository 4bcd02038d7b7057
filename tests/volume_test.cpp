// The volume unit (000 §13, Fig. 15): the layout's conflict-free proof, the marcher's drift,
// the unit against its ideal (exactly at the W-bit position, within a bound at the exact
// one), linear and quadratic fields, the volume's faces, the page model's figures, the
// sources, and the ideal against scipy.ndimage.map_coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>

#include "volume/layout.hpp"
#include "volume/marcher.hpp"
#include "volume/ray_sets.hpp"
#include "volume/sources.hpp"
#include "volume/unit.hpp"
#include "volume/volume_ideal.hpp"

namespace tmu::volume {
namespace {

constexpr double kUnit = 1 << kPosFrac;

VoxelGrid random_grid(uint32_t nx, uint32_t ny, uint32_t nz, uint64_t seed) {
  std::mt19937_64 rng(seed);
  VoxelGrid g(nx, ny, nz);
  for (uint8_t& v : g.voxels) v = static_cast<uint8_t>(rng());
  return g;
}

Point to_point(const Position& p) { return {p[0] / kUnit, p[1] / kUnit, p[2] / kUnit}; }

// The position the unit's weights see: clamped, fractions truncated to W bits.
Point truncated_point(const VoxelGrid& g, const Position& p, int w) {
  const uint32_t n[3] = {g.nx, g.ny, g.nz};
  Point out;
  for (size_t a = 0; a < 3; ++a) {
    const double c = std::clamp(p[a] / kUnit, 0.0, n[a] - 1.0);
    out[a] = std::floor(c * (1 << w)) / (1 << w);
  }
  return out;
}

// ---- the layout ----------------------------------------------------------------------------

TEST(VolumeLayoutTest, EveryVoxelHasItsOwnCell) {
  for (auto [nx, ny, nz] : {std::array<uint32_t, 3>{5, 6, 7}, {32, 16, 24}, {17, 33, 9}}) {
    const VolumeGeometry g(nx, ny, nz);
    std::set<std::pair<unsigned, uint32_t>> seen;
    for (uint32_t z = 0; z < nz; ++z) {
      for (uint32_t y = 0; y < ny; ++y) {
        for (uint32_t x = 0; x < nx; ++x) {
          const auto c = g.cell(x, y, z);
          EXPECT_EQ(c.bank, (x & 1) + 2 * (y & 1));
          EXPECT_LT(c.address, g.bank_cells());
          EXPECT_TRUE(seen.insert({c.bank, c.address}).second) << x << " " << y << " " << z;
        }
      }
    }
  }
}

TEST(VolumeLayoutTest, ABrickIsOnePageOfEachBank) {
  const VolumeGeometry g(40, 40, 20);  // 3 x 5 x 2 bricks of 16 x 8 x 16 voxels
  // Brick (1, 4, 1): voxels x 16..31, y 32..39, z 16..19 (the last, partial).
  for (uint32_t z = 16; z < 20; ++z) {
    for (uint32_t y = 32; y < 40; ++y) {
      for (uint32_t x = 16; x < 32; ++x) {
        EXPECT_EQ(g.cell(x, y, z).address >> 9, 1u + 3 * (4 + 5 * 1));
      }
    }
  }
  EXPECT_EQ(g.bank_cells(), 3u * 5 * 2 * 512);
  EXPECT_EQ(VolumeGeometry(256, 128, 128).bank_cells(), 1u << 20);  // the patent's raw set
}

TEST(VolumeLayoutTest, RejectsSizesItCannotHold) {
  EXPECT_THROW(VolumeGeometry(1, 8, 8), std::invalid_argument);
  EXPECT_THROW(VolumeGeometry(8, 513, 8), std::invalid_argument);
  EXPECT_NO_THROW(VolumeGeometry(256, 256, 128));  // 2^21 cells a bank: the most there is
  EXPECT_THROW(VolumeGeometry(256, 256, 136), std::invalid_argument);
}

// The proof: at every corner position of a small and a medium volume, in both modes, each
// access reads the voxels Fig. 15's schedule names (written here again, independently of
// unit.cpp), those inside the volume, each in its own bank.
TEST(VolumeLayoutTest, EveryAccessOfEveryPositionIsConflictFree) {
  // {x offsets}, {y offsets}, z offset; offsets from (i0, j0, k0); "1" of x is i1 (clamped).
  struct Sched {
    int x[2], y[2], z;
  };
  const Sched order[8] = {{{0, 1}, {0, 1}, 0},  {{0, 1}, {0, 1}, 1},  {{-1, 2}, {0, 1}, 0},
                          {{-1, 2}, {0, 1}, 1}, {{0, 1}, {-1, 2}, 0}, {{0, 1}, {-1, 2}, 1},
                          {{0, 1}, {0, 1}, -1}, {{0, 1}, {0, 1}, 2}};
  uint64_t checked = 0;
  for (auto [nx, ny, nz] : {std::array<uint32_t, 3>{5, 6, 7}, {32, 32, 32}, {2, 3, 2}}) {
    const VolumeGeometry g(nx, ny, nz);
    const long n[3] = {long(nx), long(ny), long(nz)};
    for (uint32_t z = 0; z < nz; ++z) {
      for (uint32_t y = 0; y < ny; ++y) {
        for (uint32_t x = 0; x < nx; ++x) {
          const long c0[3] = {long(x), long(y), long(z)};
          // Fraction 0 and a fraction > 0 (different i1 only on the last voxel).
          for (int32_t f : {0, 0x8000}) {
            const Position pos = {int32_t(x << 16) + f, int32_t(y << 16) + f, int32_t(z << 16) + f};
            for (Mode mode : {Mode::kValue, Mode::kRaw}) {
              const auto plan = plan_accesses(g, pos, mode);
              ASSERT_EQ(plan.size(), size_t(accesses_per_resample(mode)));
              for (size_t a = 0; a < plan.size(); ++a) {
                std::set<std::array<long, 3>> want;
                for (int ox : order[a].x) {
                  for (int oy : order[a].y) {
                    long v[3] = {c0[0] + ox, c0[1] + oy, c0[2] + order[a].z};
                    const int off[3] = {ox, oy, order[a].z};
                    bool inside = true;
                    for (int k = 0; k < 3; ++k) {
                      if (off[k] == 1) v[k] = std::min(v[k], n[k] - 1);  // i1
                      inside = inside && v[k] >= 0 && v[k] < n[k];
                    }
                    if (inside) want.insert({v[0], v[1], v[2]});
                  }
                }
                std::set<unsigned> banks;
                for (const auto& v : want) {
                  EXPECT_TRUE(
                      banks.insert(g.cell(uint32_t(v[0]), uint32_t(v[1]), uint32_t(v[2])).bank)
                          .second)
                      << "bank read twice: access " << a + 1 << " at " << x << " " << y << " " << z;
                }
                std::set<std::array<long, 3>> got;
                for (size_t b = 0; b < kVolumeBanks; ++b) {
                  if (!plan[a].voxel[b]) continue;
                  const Voxel& v = *plan[a].voxel[b];
                  got.insert({long(v.x), long(v.y), long(v.z)});
                  EXPECT_EQ(g.cell(v.x, v.y, v.z).bank, b);
                  EXPECT_EQ(g.cell(v.x, v.y, v.z).address, *plan[a].address[b]);
                }
                EXPECT_EQ(got, want) << "access " << a + 1 << " at " << x << " " << y << " " << z;
                ++checked;
              }
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, (5u * 6 * 7 + 32u * 32 * 32 + 2u * 3 * 2) * 2 * 10);
}

// ---- the marcher ---------------------------------------------------------------------------

TEST(VolumeMarcherTest, AccumulationEqualsExactMultiplication) {
  std::mt19937_64 rng(11);
  std::cout << "seed 11\n";
  for (int r = 0; r < 200; ++r) {
    Ray ray;
    ray.count = r < 10 ? 65535 : 512 + uint32_t(rng() % 4096);
    for (size_t a = 0; a < 3; ++a) {
      // Steps of either sign, some longer than a voxel, within range for the whole ray.
      const int64_t max_step = (int64_t{250} << 16) / ray.count;
      ray.step[a] = int32_t(int64_t(rng() % uint64_t(2 * max_step + 1)) - max_step);
      ray.start[a] = int32_t((int64_t{256} << 16) + int64_t(rng() % (1 << 16)) - 32768);
    }
    ASSERT_TRUE(ray_in_range(ray));
    const auto p = march(ray);
    ASSERT_EQ(p.size(), ray.count);
    for (uint32_t n = 0; n < ray.count; ++n) {
      for (size_t a = 0; a < 3; ++a) {
        ASSERT_EQ(p[n][a], ray.start[a] + int64_t{ray.step[a]} * n) << r << " " << n;
      }
    }
  }
}

TEST(VolumeMarcherTest, NegativeLongAndAxisParallelSteps) {
  Ray ray{{quantise(200.25), quantise(3.5), quantise(7)}, {quantise(-1.75), 0, quantise(3.5)}, 100};
  ASSERT_TRUE(ray_in_range(ray));
  const auto p = march(ray);
  EXPECT_EQ(p[99][0], quantise(200.25 - 99 * 1.75));  // -1.75 is exact in 16 bits
  EXPECT_EQ(p[99][1], quantise(3.5));                 // axis-parallel: y never moves
  EXPECT_EQ(p[99][2], quantise(7 + 99 * 3.5));
  // The accumulator wraps at 26 bits; the host rejects a ray that would.
  EXPECT_EQ(wrap_pos(int64_t{1} << 25), -(1 << 25));
  EXPECT_FALSE(ray_in_range(Ray{{quantise(500), 0, 0}, {quantise(7.5), 0, 0}, 3}));
  EXPECT_FALSE(ray_in_range(Ray{{0, 0, 0}, {quantise(8), 0, 0}, 1}));  // step >= 8
}

// The only drift against the real ray is the host's quantisation: (1 + n) 2^-17 per axis.
TEST(VolumeMarcherTest, DriftAgainstTheRealRayIsBounded) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> s(0, 10), d(-0.24, 0.24);  // in range for 2048
  double worst = 0;                                                 // in units of (1 + n) 2^-17
  for (int r = 0; r < 100; ++r) {
    const Point start{s(rng), s(rng), s(rng)}, step{d(rng), d(rng), d(rng)};
    const Ray ray{{quantise(start[0]), quantise(start[1]), quantise(start[2])},
                  {quantise(step[0]), quantise(step[1]), quantise(step[2])},
                  2048};
    ASSERT_TRUE(ray_in_range(ray));
    const auto p = march(ray);
    for (uint32_t n = 0; n < ray.count; ++n) {
      const Point exact = ideal_location(start, step, n);
      for (size_t a = 0; a < 3; ++a) {
        const double err = std::abs(p[n][a] / kUnit - exact[a]);
        worst = std::max(worst, err / ((1.0 + n) / (1 << 17)));
      }
    }
  }
  std::cout << "worst drift / bound " << worst << "\n";
  EXPECT_LE(worst, 1.0 + 1e-9);
}

// ---- the unit ------------------------------------------------------------------------------

TEST(VolumeUnitTest, AxisCorners) {
  EXPECT_EQ(axis_corners(0, 10, 8).i1, 1u);
  const AxisCorners last = axis_corners(9 << 16, 10, 8);
  EXPECT_EQ(last.i0, 9u);
  EXPECT_EQ(last.i1, 9u);  // the far corner clamped: one read, weight 0
  EXPECT_EQ(last.w, 0u);
  EXPECT_EQ(axis_corners(-5 << 16, 10, 8).i0, 0u);  // outside: the nearest face
  EXPECT_EQ(axis_corners(20 << 16, 10, 8).i0, 9u);
  EXPECT_EQ(axis_corners((3 << 16) + 0xFFFF, 10, 4).w, 15u);  // truncated to W bits
  EXPECT_EQ(axis_corners((3 << 16) + 0x8000, 10, 8).w, 128u);
}

// Fraction 0: the value is the voxel; the gradient the node's difference (SQ9.4: 8 D).
TEST(VolumeUnitTest, NodesReturnTheVoxelAndItsDifference) {
  const VoxelGrid grid = random_grid(6, 5, 7, 3);
  const VolumeMemory mem = load(grid);
  for (uint32_t z = 0; z < grid.nz; ++z) {
    for (uint32_t y = 0; y < grid.ny; ++y) {
      for (uint32_t x = 0; x < grid.nx; ++x) {
        const Resample r =
            resample(mem, {Mode::kRaw, 8}, {int32_t(x << 16), int32_t(y << 16), int32_t(z << 16)});
        EXPECT_EQ(r.value, grid.at(x, y, z));
        for (int a = 0; a < 3; ++a) {
          EXPECT_EQ(r.gradient[size_t(a)], std::lround(16 * ideal_node_gradient(grid, x, y, z, a)));
        }
      }
    }
  }
}

// Gradients at the first and last voxel of each axis, by hand: f = 10 t^2 along one axis
// t = 0..3 (0, 10, 40, 90): D = 2 (10 - 0) = 20 at 0 (one-sided), 40 - 0 = 40 at 1,
// 90 - 10 = 80 at 2, 2 (90 - 40) = 100 at 3; the port's SQ9.4 raw value is 8 D.
TEST(VolumeUnitTest, GradientsOnTheFacesAreOneSided) {
  for (int axis = 0; axis < 3; ++axis) {
    VoxelGrid g(4, 4, 4);
    for (uint32_t z = 0; z < 4; ++z) {
      for (uint32_t y = 0; y < 4; ++y) {
        for (uint32_t x = 0; x < 4; ++x) {
          const uint32_t t = axis == 0 ? x : axis == 1 ? y : z;
          g.at(x, y, z) = uint8_t(10 * t * t);
        }
      }
    }
    const VolumeMemory mem = load(g);
    const int32_t want[4] = {20, 40, 80, 100};
    for (int32_t t = 0; t < 4; ++t) {
      Position p = {1 << 16, 2 << 16, 3 << 16};
      p[size_t(axis)] = t << 16;
      const Resample r = resample(mem, {Mode::kRaw, 8}, p);
      EXPECT_EQ(r.gradient[size_t(axis)], 8 * want[t]) << axis << " " << t;
      EXPECT_EQ(r.gradient[size_t((axis + 1) % 3)], 0);
      EXPECT_EQ(ideal_resample(g, to_point(p)).gradient[size_t(axis)], want[t] / 2.0);
    }
    // Halfway between the last two voxels: (80 + 100) / 2 = 90; value (40 + 90) / 2 = 65.
    Position p = {1 << 16, 2 << 16, 3 << 16};
    p[size_t(axis)] = (2 << 16) + 0x8000;
    const Resample r = resample(mem, {Mode::kRaw, 8}, p);
    EXPECT_EQ(r.gradient[size_t(axis)], 8 * 90);
    EXPECT_EQ(r.value, 65);
  }
}

// A linear field: both models exact, the gradient too (on the faces as well: one-sided
// differences of a linear field are exact). f = 10 + 3x + 2y + 5z on 16 x 16 x 16 (max 160).
TEST(VolumeUnitTest, LinearFieldIsReconstructedExactly) {
  VoxelGrid g(16, 16, 16);
  for (uint32_t z = 0; z < 16; ++z) {
    for (uint32_t y = 0; y < 16; ++y) {
      for (uint32_t x = 0; x < 16; ++x) g.at(x, y, z) = uint8_t(10 + 3 * x + 2 * y + 5 * z);
    }
  }
  const VolumeMemory mem = load(g);
  std::mt19937_64 rng(4);
  std::cout << "seed 4\n";
  for (int i = 0; i < 20000; ++i) {
    Position p;
    // Positions of W = 8 fraction bits (no truncation); faces, edges and corners included.
    for (int32_t& c : p) {
      const uint64_t k = rng() % 8;
      c = k == 0 ? 0 : k == 1 ? (15 << 16) : int32_t(rng() % (15 << 8)) << 8;
    }
    const int64_t v256 =
        (10 << 8) + (3 * int64_t{p[0]} + 2 * int64_t{p[1]} + 5 * int64_t{p[2]}) / 256;
    const Resample r = resample(mem, {Mode::kRaw, 8}, p);
    ASSERT_EQ(r.value, (v256 + 128) >> 8) << p[0] << " " << p[1] << " " << p[2];
    ASSERT_EQ(r.gradient, (std::array<int32_t, 3>{16 * 3, 16 * 2, 16 * 5}));  // SQ9.4
    const IdealResample id = ideal_resample(g, to_point(p));
    ASSERT_NEAR(id.value, double(v256) / 256.0, 1e-12);
    ASSERT_NEAR(id.gradient[0], 3, 1e-12);
    ASSERT_NEAR(id.gradient[1], 2, 1e-12);
    ASSERT_NEAR(id.gradient[2], 5, 1e-12);
  }
}

// f = x^2 (0..225 on 16 voxels): the central difference (f(x+1) - f(x-1)) / 2 = 2x exactly at
// every inner node; D = 4x. On the faces the one-sided 1 and 29 (D 2 and 58). SQ9.4: 8 D.
TEST(VolumeUnitTest, CentralDifferencesExactOnAQuadraticField) {
  VoxelGrid g(16, 4, 4);
  for (uint32_t z = 0; z < 4; ++z) {
    for (uint32_t y = 0; y < 4; ++y) {
      for (uint32_t x = 0; x < 16; ++x) g.at(x, y, z) = uint8_t(x * x);
    }
  }
  const VolumeMemory mem = load(g);
  for (int32_t x = 0; x < 16; ++x) {
    const Position p = {x << 16, 1 << 16, 2 << 16};
    const int32_t want = x == 0 ? 2 : x == 15 ? 58 : 4 * x;
    EXPECT_EQ(resample(mem, {Mode::kRaw, 8}, p).gradient[0], 8 * want) << x;
    EXPECT_DOUBLE_EQ(ideal_resample(g, to_point(p)).gradient[0], want / 2.0) << x;
  }
}

// Random rays over a random volume: the golden value equals the ideal at the position the
// W-bit weights stand for, rounded half up (its values are dyadic: exact in double); the
// gradient likewise in SQ9.4 units (the ideal's dyadic values x 16, exact). Includes negative
// steps, steps longer than a voxel, axis-parallel rays and rays leaving the volume (clamped to the
// nearest face).
TEST(VolumeUnitTest, GoldenIsTheIdealAtItsWeightsRoundedOnce) {
  const VoxelGrid g = random_grid(13, 10, 9, 5);
  const VolumeMemory mem = load(g);
  std::mt19937_64 rng(6);
  std::cout << "seed 6\n";
  std::uniform_real_distribution<double> s(-1, 14), d(-2.5, 2.5);
  for (int w : {8, 5, 1}) {
    for (int r = 0; r < 300; ++r) {
      Ray ray{{quantise(s(rng)), quantise(s(rng)), quantise(s(rng))},
              {quantise(d(rng)), quantise(d(rng)), quantise(d(rng))},
              40};
      if (r % 10 == 0) ray.step = {0, 0, quantise(0.37)};  // axis-parallel
      if (r % 10 == 1) ray.step = {quantise(-1.3), 0, 0};  // negative, axis-parallel
      const auto out = cast(mem, {Mode::kRaw, w}, ray);
      const auto pos = march(ray);
      for (size_t n = 0; n < out.size(); ++n) {
        const IdealResample id = ideal_resample(g, truncated_point(g, pos[n], w));
        ASSERT_EQ(out[n].value, std::floor(id.value + 0.5)) << w << " " << r << " " << n;
        for (size_t a = 0; a < 3; ++a) {
          ASSERT_EQ(out[n].gradient[a], std::floor(16 * id.gradient[a] + 0.5))
              << w << " " << r << " " << n << " " << a;
        }
      }
    }
  }
}

// Against the ideal at the exact position: the rounding (1/2 a value, 1/32 of a gradient: half
// an SQ9.4 unit) plus the weights' truncation, less than 2^-W per axis, times the largest change
// along that axis over the cell's four edges (the interpolant is linear along each axis); on
// random rays.
TEST(VolumeUnitTest, GoldenWithinItsBoundOfTheIdeal) {
  const VoxelGrid g = random_grid(16, 16, 16, 7);
  const VolumeMemory mem = load(g);
  std::mt19937_64 rng(8);
  std::cout << "seed 8\n";
  std::uniform_real_distribution<double> s(0, 15), d(-0.6, 0.6);
  double worst_v = 0, worst_g = 0, max_v = 0, max_g = 0;
  Ray ray;
  for (int w : {8, 6}) {
    for (int i = 0; i < 20000; ++i) {
      // Random rays (some leave the volume), 50 locations each; the ideal's location is its
      // own start + n step of the quantised ray.
      if (i % 50 == 0) {
        ray = {{quantise(s(rng)), quantise(s(rng)), quantise(s(rng))},
               {quantise(d(rng)), quantise(d(rng)), quantise(d(rng))},
               50};
      }
      const Position p = march(ray)[size_t(i % 50)];
      const Resample r = resample(mem, {Mode::kRaw, w}, p);
      const IdealResample id =
          ideal_resample(g, ideal_location(to_point(ray.start), to_point(ray.step), i % 50));
      const Point x = to_point(p);
      long i0[3];
      for (size_t a = 0; a < 3; ++a) i0[a] = std::min(long(std::clamp(x[a], 0.0, 15.0)), 14L);
      // The largest change along each axis over the cell's edges, of f and of each gradient
      // component.
      double dv[3] = {0, 0, 0}, dg[3][3] = {};
      for (int a = 0; a < 3; ++a) {
        for (int k = 0; k < 8; ++k) {
          if (k & (1 << a)) continue;
          long c0[3] = {i0[0] + (k & 1), i0[1] + ((k >> 1) & 1), i0[2] + ((k >> 2) & 1)};
          long c1[3] = {c0[0], c0[1], c0[2]};
          c1[a] += 1;
          dv[a] = std::max(
              dv[a], std::abs(double(g.at(uint32_t(c1[0]), uint32_t(c1[1]), uint32_t(c1[2]))) -
                              g.at(uint32_t(c0[0]), uint32_t(c0[1]), uint32_t(c0[2]))));
          for (int b = 0; b < 3; ++b) {
            dg[b][a] = std::max(dg[b][a], std::abs(ideal_node_gradient(g, c1[0], c1[1], c1[2], b) -
                                                   ideal_node_gradient(g, c0[0], c0[1], c0[2], b)));
          }
        }
      }
      const double step = 1.0 / (1 << w);
      const double bound_v = 0.5 + step * (dv[0] + dv[1] + dv[2]);
      const double err_v = std::abs(r.value - id.value);
      ASSERT_LE(err_v, bound_v + 1e-9);
      worst_v = std::max(worst_v, err_v / bound_v);
      max_v = std::max(max_v, err_v);
      for (size_t b = 0; b < 3; ++b) {
        const double bound_g = 1.0 / 32 + step * (dg[b][0] + dg[b][1] + dg[b][2]);
        const double err_g = std::abs(r.gradient[b] / 16.0 - id.gradient[b]);
        ASSERT_LE(err_g, bound_g + 1e-9);
        worst_g = std::max(worst_g, err_g / bound_g);
        max_g = std::max(max_g, err_g);
      }
    }
  }
  std::cout << "value: largest error " << max_v << ", of its bound " << worst_v
            << "; gradient: largest error " << max_g << ", of its bound " << worst_g << "\n";
}

TEST(VolumeUnitTest, ValueModeReadsTwiceRawModeEightTimes) {
  const VoxelGrid g = random_grid(20, 20, 20, 9);
  const VolumeMemory mem = load(g);
  const Ray ray{
      {quantise(1.5), quantise(2.25), quantise(0.5)}, {quantise(0.5), 0, quantise(0.75)}, 20};
  for (Mode mode : {Mode::kValue, Mode::kRaw}) {
    texram::PageModel pages;
    std::vector<Access> accesses;
    const auto out = cast(mem, {mode, 8}, ray, &pages, &accesses);
    EXPECT_EQ(pages.stats().accesses, 20u * uint64_t(accesses_per_resample(mode)));
    ASSERT_EQ(accesses.size(), pages.stats().accesses);
    // The record is the plan, location by location.
    const auto pos = march(ray);
    for (size_t n = 0; n < pos.size(); ++n) {
      const auto plan = plan_accesses(mem.geometry, pos[n], mode);
      for (size_t a = 0; a < plan.size(); ++a) {
        EXPECT_EQ(accesses[n * plan.size() + a], plan[a]);
      }
      // Value mode gives the same value as raw mode, and no gradient.
      if (mode == Mode::kValue) {
        EXPECT_EQ(out[n].value, resample(mem, {Mode::kRaw, 8}, pos[n]).value);
        EXPECT_EQ(out[n].gradient, (std::array<int32_t, 3>{}));
      }
    }
    // The first location faults in each bank it reads, later ones only on a new brick.
    EXPECT_GE(pages.stats().page_faults, 4u);
  }
}

// A run cut into pieces counts as the one long run when each piece's page model starts with the
// pages the last one left open (what the renderer's hls and rtl engines do between runs of the
// block, render/volume_engine_block.hpp); starting each piece with no page open counts more.
TEST(VolumeUnitTest, APageModelFromOpenPagesContinuesTheLongRun) {
  const VoxelGrid g = random_grid(40, 30, 50, 3);
  const VolumeMemory mem = load(g);
  std::vector<Access> accesses;
  std::mt19937_64 rng(5);
  for (int r = 0; r < 60; ++r) {
    const auto u = [&rng](double lo, double hi) {
      return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1p-53;
    };
    const Ray ray{{quantise(u(0, 39)), quantise(u(0, 29)), quantise(u(0, 49))},
                  {quantise(u(-1, 1)), quantise(u(-1, 1)), quantise(u(-1, 1))},
                  20};
    cast(mem, {Mode::kRaw, 8}, ray, nullptr, &accesses);
  }
  const auto banks = [](const Access& a) {
    std::array<std::optional<uint32_t>, 8> b{};
    std::copy(a.address.begin(), a.address.end(), b.begin());
    return b;
  };
  texram::PageModel whole;
  for (const Access& a : accesses) whole.access(banks(a));
  for (size_t piece : {1u, 7u, 97u, 1000u}) {
    texram::PageStats carried, fresh;
    texram::OpenPages open{};
    for (size_t i = 0; i < accesses.size(); i += piece) {
      texram::PageModel p(open), q;
      for (size_t k = i; k < std::min(i + piece, accesses.size()); ++k) {
        p.access(banks(accesses[k]));
        q.access(banks(accesses[k]));
      }
      open = p.open_pages();
      for (auto [sum, part] : {std::pair{&carried, p.stats()}, std::pair{&fresh, q.stats()}}) {
        sum->accesses += part.accesses;
        sum->bank_reads += part.bank_reads;
        sum->page_faults += part.page_faults;
        sum->slow_accesses += part.slow_accesses;
      }
    }
    EXPECT_EQ(carried, whole.stats()) << "pieces of " << piece;
    EXPECT_GT(fresh.page_faults, whole.stats().page_faults) << "pieces of " << piece;
  }
}

// blend() is what a unit with a memory port computes from the bytes its accesses brought back
// (the hls model): the same as resample() whatever an idle bank delivers; it rejects a
// location without the mode's accesses.
TEST(VolumeUnitTest, BlendReadsOnlyWhatTheAccessesDelivered) {
  const VoxelGrid g = random_grid(7, 5, 9, 17);
  const VolumeMemory mem = load(g);
  std::mt19937_64 rng(18);
  for (int i = 0; i < 3000; ++i) {
    const Position pos = {static_cast<int32_t>(rng() % (9 << 16)) - (1 << 16),
                          static_cast<int32_t>(rng() % (7 << 16)) - (1 << 16),
                          static_cast<int32_t>(rng() % (11 << 16)) - (1 << 16)};
    const Config config{rng() % 2 ? Mode::kRaw : Mode::kValue, 1 + static_cast<int>(rng() % 8)};
    const std::vector<Access> plan = plan_accesses(mem.geometry, pos, config.mode);
    std::vector<AccessData> bytes(plan.size());
    for (size_t a = 0; a < plan.size(); ++a) {
      for (size_t b = 0; b < kVolumeBanks; ++b) {
        bytes[a][b] = plan[a].address[b] ? mem.banks[b][*plan[a].address[b]]
                                         : static_cast<uint8_t>(rng());  // idle: garbage
      }
    }
    ASSERT_EQ(blend(mem.geometry, config, pos, plan, bytes), resample(mem, config, pos)) << i;
  }
  const Position pos = {1 << 16, 1 << 16, 1 << 16};
  std::vector<Access> plan = plan_accesses(mem.geometry, pos, Mode::kRaw);
  std::vector<AccessData> bytes(plan.size());
  EXPECT_THROW(blend(mem.geometry, {Mode::kValue, 8}, pos, plan, bytes), std::invalid_argument);
  plan.pop_back();
  bytes.pop_back();
  EXPECT_THROW(blend(mem.geometry, {Mode::kRaw, 8}, pos, plan, bytes), std::invalid_argument);
  EXPECT_THROW(blend(mem.geometry, {Mode::kRaw, 0}, pos, plan, bytes), std::invalid_argument);
}

// ---- sources -------------------------------------------------------------------------------

TEST(VolumeSourcesTest, MarschnerLobb) {
  // f(0, 0, 0) = (1 - 0 + 0.25 (1 + cos 12 pi)) / 2.5 = 0.6 -> 153.
  EXPECT_DOUBLE_EQ(marschner_lobb(0, 0, 0), 0.6);
  EXPECT_NEAR(marschner_lobb(0, 0, 1), 0.5 / 2.5, 1e-15);  // sin(pi/2) = 1: (0 + 0.5) / 2.5
  const VoxelGrid g = marschner_lobb_grid(41);
  EXPECT_EQ(g.at(20, 20, 20), 153);
  EXPECT_EQ(g.at(20, 20, 40), 51);                                      // 0.2 * 255
  EXPECT_EQ(*std::max_element(g.voxels.begin(), g.voxels.end()), 255);  // f = 1: z = -1, rho = 1
}

// The field on a grid of other sides per axis (the co-simulation block's volumes): each axis
// over [-1, 1], the cube's voxels where the sides agree.
TEST(VolumeSourcesTest, MarschnerLobbOnABox) {
  const VoxelGrid box = marschner_lobb_grid(41, 21, 11);
  const VoxelGrid cube = marschner_lobb_grid(41);
  EXPECT_EQ(box.at(20, 10, 5), 153);                   // the centre (0, 0, 0)
  EXPECT_EQ(box.at(40, 20, 10), cube.at(40, 40, 40));  // the corner (1, 1, 1)
  EXPECT_EQ(box.at(0, 0, 0), cube.at(0, 0, 0));
  EXPECT_EQ(box.at(12, 4, 5), cube.at(12, 8, 20));  // (-0.4, -0.6, 0)
}

// The reconstruction error on Marschner-Lobb's 41^3 grid (its customary sampling, 2/40 per
// voxel) against 255 f at random points: the trilinear filter's (the ideal's) error and the
// golden's, which adds at most 1/2 + 2^-8 times three edge changes of up to ~70 per sample.
TEST(VolumeSourcesTest, MarschnerLobbReconstruction) {
  const uint32_t n = 41;
  const VoxelGrid g = marschner_lobb_grid(n);
  const VolumeMemory mem = load(g);
  std::mt19937_64 rng(15);
  std::cout << "seed 15\n";
  std::uniform_real_distribution<double> u(0, n - 1);
  double se_g = 0, se_i = 0;
  const int count = 20000;
  for (int i = 0; i < count; ++i) {
    const Position p = {quantise(u(rng)), quantise(u(rng)), quantise(u(rng))};
    const Point x = to_point(p);
    const double f = 255 * marschner_lobb(-1 + 2 * x[0] / (n - 1), -1 + 2 * x[1] / (n - 1),
                                          -1 + 2 * x[2] / (n - 1));
    const double e_g = resample(mem, {Mode::kValue, 8}, p).value - f;
    const double e_i = ideal_resample(g, x).value - f;
    se_g += e_g * e_g;
    se_i += e_i * e_i;
  }
  const double rms_g = std::sqrt(se_g / count), rms_i = std::sqrt(se_i / count);
  std::cout << "Marschner-Lobb 41^3, RMS error in voxel values: golden " << rms_g << ", ideal "
            << rms_i << "\n";
  EXPECT_LE(std::abs(rms_g - rms_i), 0.5);
}

// The gradient's direction on a sphere distance field against the true normal: 64^3, radius
// 24 voxels, 8 values per voxel, resample locations within 2 voxels of the surface.
TEST(VolumeSourcesTest, SphereGradientDirection) {
  const VoxelGrid g = sphere_grid(64, 64, 64, 24, 8);
  const auto c = sphere_centre(g);
  EXPECT_EQ(g.at(0, 0, 0), 0);
  EXPECT_EQ(g.at(32, 32, 32), 255);
  const VolumeMemory mem = load(g);
  std::mt19937_64 rng(10);
  std::cout << "seed 10\n";
  std::uniform_real_distribution<double> u(-1, 1), rr(22, 26);
  double sum_g = 0, max_g = 0, sum_i = 0, max_i = 0, max_gi = 0;
  const int count = 20000;
  for (int i = 0; i < count; ++i) {
    Point dir{u(rng), u(rng), u(rng)};
    const double len = std::hypot(dir[0], dir[1], dir[2]);
    if (len < 0.1 || len > 1) {
      --i;
      continue;
    }
    const double r = rr(rng);
    const Position p = {quantise(c[0] + r * dir[0] / len), quantise(c[1] + r * dir[1] / len),
                        quantise(c[2] + r * dir[2] / len)};
    const Point x = to_point(p);
    const Point normal{x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    auto angle = [&](double gx, double gy, double gz) {
      const double dot = -(gx * normal[0] + gy * normal[1] + gz * normal[2]);
      return std::acos(std::clamp(
                 dot / (std::hypot(gx, gy, gz) * std::hypot(normal[0], normal[1], normal[2])), -1.0,
                 1.0)) *
             180 / std::numbers::pi;
    };
    const Resample s = resample(mem, {Mode::kRaw, 8}, p);
    const IdealResample id = ideal_resample(g, x);
    const double ag = angle(s.gradient[0], s.gradient[1], s.gradient[2]);
    // Golden against ideal: 1/32 rounding per component of a gradient of about 8 (and the
    // weights' 2^-8 truncation) turn it by at most atan(sqrt(3) / 32 / 7.5) = 0.41 degrees.
    const double gi =
        std::acos(std::clamp(
            (s.gradient[0] / 16.0 * id.gradient[0] + s.gradient[1] / 16.0 * id.gradient[1] +
             s.gradient[2] / 16.0 * id.gradient[2]) /
                (std::hypot(s.gradient[0] / 16.0, s.gradient[1] / 16.0, s.gradient[2] / 16.0) *
                 std::hypot(id.gradient[0], id.gradient[1], id.gradient[2])),
            -1.0, 1.0)) *
        180 / std::numbers::pi;
    ASSERT_LE(gi, 0.41) << i;
    max_gi = std::max(max_gi, gi);
    const double ai = angle(id.gradient[0], id.gradient[1], id.gradient[2]);
    sum_g += ag;
    sum_i += ai;
    max_g = std::max(max_g, ag);
    max_i = std::max(max_i, ai);
  }
  std::cout << "sphere normal angle error (degrees): golden mean " << sum_g / count << " max "
            << max_g << "; ideal (same voxels) mean " << sum_i / count << " max " << max_i
            << "; golden against ideal max " << max_gi << "\n";
  // The measured figures (docs/volume.md), rounded up: the voxels' 8 bits and the central
  // differences' error on the curved surface dominate, not the golden arithmetic.
  EXPECT_LT(sum_g / count, 0.90);
  EXPECT_LT(max_g, 4.0);
}

// ---- figures -------------------------------------------------------------------------------

struct Figures {
  double resamples = 0, accesses = 0, faults = 0, slow = 0;
};

Figures run_rays(const VolumeMemory& mem, Mode mode, const std::vector<Ray>& rays) {
  texram::PageModel pages;
  Figures f;
  for (const Ray& ray : rays) {
    cast(mem, {mode, 8}, ray, &pages);
    f.resamples += ray.count;
  }
  f.accesses = double(pages.stats().accesses);
  f.faults = double(pages.stats().page_faults);
  f.slow = double(pages.stats().slow_accesses);
  return f;
}

// The patent's two data sets on four chips (000 §5): a 64 x 128 x 128 RGBA set, one
// component per chip (each chip resamples all 1 M locations, value mode); a 256 x 128 x 128
// raw set in four 64 x 128 x 128 slabs, one per chip (each chip 1 M locations of its slab,
// raw mode). Time = locations x (accesses + slow accesses) x 30 ns.
TEST(VolumeFiguresTest, PatentDataSets) {
  const VoxelGrid g = marschner_lobb_grid(128);
  VoxelGrid slab(64, 128, 128);
  for (uint32_t z = 0; z < 128; ++z) {
    for (uint32_t y = 0; y < 128; ++y) {
      for (uint32_t x = 0; x < 64; ++x) slab.at(x, y, z) = g.at(x + 32, y, z);
    }
  }
  const VolumeMemory mem = load(slab);
  // Page faults and slow accesses per ray set and mode (the page model's exact counts, as
  // docs/volume.md tables them): {value faults, value slow, raw faults, raw slow}.
  const std::map<std::string, std::array<double, 4>> want = {
      {"z", {259080, 65536, 4956890, 1546392}},
      {"x", {700230, 223104, 5388805, 1700583}},
      {"oblique", {293472, 92992, 4665438, 1559252}}};
  std::cout << "set     mode   acc/res faults/res slow/res  time_ms (four chips)\n";
  for (const char* set : {"z", "x", "oblique"}) {
    for (Mode mode : {Mode::kValue, Mode::kRaw}) {
      const Figures f = run_rays(mem, mode, figure_rays(set, 64, 128, 128));
      EXPECT_EQ(f.resamples, 64.0 * 128 * 128);
      EXPECT_EQ(f.accesses, f.resamples * accesses_per_resample(mode));
      const size_t m = mode == Mode::kRaw ? 2 : 0;
      EXPECT_EQ(f.faults, want.at(set)[m]) << set;
      EXPECT_EQ(f.slow, want.at(set)[m + 1]) << set;
      const double ms = (f.accesses + f.slow) * texram::kAccessNs * 1e-6;
      std::printf("%-8s %-6s %7.3f %10.4f %8.4f %8.1f   faults %.0f slow %.0f\n", set,
                  mode == Mode::kRaw ? "raw" : "value", f.accesses / f.resamples,
                  f.faults / f.resamples, f.slow / f.resamples, ms, f.faults, f.slow);
    }
  }
}

// ---- the ideal against scipy ---------------------------------------------------------------

// scipy.ndimage.map_coordinates(order=1, mode='nearest') is trilinear interpolation with voxel
// centres at integers; numpy.gradient(edge_order=1) is the central difference inside and the
// one-sided one on the faces. tests/volume_scipy_check.py evaluates both on the volume and
// points written here and compares them with the ideal's values (1e-9).
TEST(VolumeIdealTest, AgreesWithScipyMapCoordinates) {
  if (std::system("/usr/bin/python3 -c 'import scipy.ndimage' 2>/dev/null") != 0) {
    GTEST_SKIP() << "python3-scipy missing";
  }
  const VoxelGrid g = random_grid(11, 9, 13, 13);
  const auto dir =
      std::filesystem::temp_directory_path() / ("tmu_volume_scipy_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream vox(dir / "voxels.bin", std::ios::binary);
    vox.write(reinterpret_cast<const char*>(g.voxels.data()), std::streamsize(g.voxels.size()));
    std::ofstream pts(dir / "points.txt");
    pts.precision(17);
    pts << g.nx << " " << g.ny << " " << g.nz << "\n";
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 2000; ++i) {
      Point p{u(rng) * (g.nx - 1), u(rng) * (g.ny - 1), u(rng) * (g.nz - 1)};
      if (i < 8)
        p = {(i & 1) ? g.nx - 1.0 : 0.0, (i & 2) ? g.ny - 1.0 : 0.0, (i & 4) ? g.nz - 1.0 : 0.0};
      const IdealResample id = ideal_resample(g, p);
      pts << p[0] << " " << p[1] << " " << p[2] << " " << id.value << " " << id.gradient[0] << " "
          << id.gradient[1] << " " << id.gradient[2] << "\n";
    }
  }
  const std::string cmd =
      "/usr/bin/python3 " TMU_SOURCE_DIR "/tests/volume_scipy_check.py " + dir.string();
  const int rc = std::system(cmd.c_str());
  std::filesystem::remove_all(dir);
  EXPECT_EQ(rc, 0);
}

}  // namespace
}  // namespace tmu::volume
