// The shading- and environment-map coordinate generator (001 §5, eq. 17-22): golden vs rtl
// vs hls bit for bit on the block's directed hard cases (angle corners, write-then-read of
// every table, the port's rules, view changes, tables at the limits where uR, vR, wR
// saturate) and random items under back-pressure; one normal per clock; the golden engine's
// table memory agrees with CoordTables::eval; and the teeth (RTL mutants: the phi + pi
// negation missing, the reflection's rounding constant; an injected wrong bit).
#include <Vtmu_coord_gen_mutant_phi_neg.h>
#include <Vtmu_coord_gen_mutant_round.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>

#include "blocks/coord_gen_block.hpp"
#include "deflect/coord_table_memory.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using deflect::CoordTableMemory;
using deflect::CoordTables;
using deflect::SphereAngle;
using deflect::TableConfig;
using deflect::ViewFrame;
constexpr auto options = testing::cosim_options;

// The memory the port loads from CoordTables::writes() evaluates every normal of the grid as
// CoordTables::eval does (eval_coords is the specification's arithmetic, shared), on the
// identity view and on random frames; the identity example of rtl/deflect/tmu_coord_gen.sv.
TEST(CoordGenCosimTest, PortLoadedTablesEvaluateAsCoordTables) {
  const TableConfig config;
  std::mt19937_64 rng(77);
  std::vector<ViewFrame> frames = {ViewFrame{}};
  for (int i = 0; i < 3; ++i) frames.push_back(random_view_frame(rng));
  for (const ViewFrame& f : frames) {
    const CoordTables tables(config, f);
    CoordTableMemory memory(config);
    memory.load(tables);
    for (uint32_t phi = 0; phi < config.grid.phi_count(); ++phi) {
      for (uint32_t theta = 0; theta < 2 * config.grid.quarter(); ++theta) {
        const deflect::MapCoords a = tables.eval({phi, theta}), b = memory.eval({phi, theta});
        ASSERT_TRUE(a.un == b.un && a.vn == b.vn && a.ur == b.ur && a.vr == b.vr && a.wr == b.wr)
            << "phi " << phi << " theta " << theta;
      }
    }
  }
  CoordTableMemory identity(config);
  identity.load(CoordTables(config, ViewFrame{}));
  const deflect::MapCoords c = identity.eval({0, 0});
  EXPECT_EQ(c.un, 0);
  EXPECT_EQ(c.vn, 0);
  EXPECT_EQ(c.ur, 0);
  EXPECT_EQ(c.wr, 16129);
  // The port's rules: -2^(W-1) stored as the limit, writes beyond a table ignored.
  EXPECT_TRUE(identity.write({deflect::kF2, 5, -512}));
  EXPECT_EQ(identity.entry(deflect::kF2, 5), -511);
  EXPECT_FALSE(identity.write({deflect::kF3, 128, 1}));
  EXPECT_FALSE(identity.write({7, 0, 1}));
}

// Directed items and 200000 random items under back-pressure, golden vs rtl (and the X
// check); every coverage case hit.
TEST(CoordGenCosimTest, DirectedAndRandomGoldenVsRtl) {
  const uint64_t seed = 20260611;
  const CoordGenBlock block(seed);
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(seed, 200'000, {"rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
  const size_t at = log.str().find("coverage:");
  if (at != std::string::npos) std::cout << log.str().substr(at);
}

TEST(CoordGenCosimTest, GoldenVsHlsVsRtlUnderHeavyBackPressure) {
  for (uint64_t seed : {7u, 8u}) {
    const CoordGenBlock block(seed);
    CosimOptions o = options(seed, 30'000, {"hls", "rtl"});
    o.in_idle = 0.6;
    o.out_stall = 0.6;
    std::stringstream log;
    const CosimResult r = run_cosim(block, o, log);
    EXPECT_TRUE(r.pass) << log.str();
    for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "not hit: " << name;
  }
}

// The parameters' other corner (PhiBits 7, ValueBits 8: a 128 x 64 grid, entries +-127, the
// dot products without rounding; the ports' upper bits ignored): golden vs hls vs rtl.
TEST(CoordGenCosimTest, SmallGridAndWidthGoldenVsHlsVsRtl) {
  const CoordGenBlock block(11, kCoordGenSmallConfig);
  CosimOptions o = options(11, 50'000, {"hls", "rtl"});
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "not hit: " << name;
}

// One item per clock, writes and requests alike: no stalls, the pipeline's three registers
// and the harness's 16 drain cycles on top.
TEST(CoordGenCosimTest, OneNormalPerClock) {
  const CoordGenBlock block(3);
  CosimOptions o = options(3, 20'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  EXPECT_LE(r.runs.at("rtl").cycles, r.items + 3 + 16 + 1) << log.str();
  EXPECT_LE(r.runs.at("hls").cycles, r.items + 20) << log.str();
}

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(uint64_t seed, size_t count, bool directed, std::stringstream& log) {
  const CoordGenBlock block(seed);
  CosimOptions o = options(seed, count, {"rtl"});
  o.directed = directed;
  o.x_check = false;
  return run_cosim(block, o, log, [](const std::string& level) -> std::unique_ptr<Engine> {
    if (level != "rtl") return nullptr;
    return make_coord_gen_rtl_engine<Model>("rtl");
  });
}

// F2, G2, H2 not negated for phi >= 2Q: the directed angle sweep alone catches it.
TEST(CoordGenCosimTest, MissingPhiNegationMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_coord_gen_mutant_phi_neg>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim coord-gen --seed 9");
}

// The reflection adds a quarter instead of half an LSB before its shift: caught by random
// normals alone (no directed items).
TEST(CoordGenCosimTest, ReflectionRoundingMutantIsCaught) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_coord_gen_mutant_round>(9, 2000, false, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

TEST(CoordGenCosimTest, InjectedFaultFailsTheRun) {
  const CoordGenBlock block(5);
  CosimOptions o = options(5, 1000, {"hls", "rtl"});
  o.inject_fault = 400;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 400"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace tmu::tb
