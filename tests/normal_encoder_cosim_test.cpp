// The normal encoder (001 §4.1): golden vs hls vs rtl, bit for bit, on the block's directed
// hard cases (zero, tiny, poles, octant boundaries, equal squares, the extreme components,
// every reachable angle-table index and every seed-table index) and random normals of any
// length under back-pressure; the paper's linear angle-table index (E = 1, M = 7) as a second
// Verilated model; one normal per clock; and proof that the comparison has teeth (RTL
// mutants: the Newton-Raphson step truncating one bit more, theta not saturating at a pole;
// an injected wrong bit).
#include <Vtmu_normal_encoder_mutant_nr.h>
#include <Vtmu_normal_encoder_mutant_pole.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include "blocks/normal_encoder_block.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using deflect::EncoderConfig;
constexpr auto options = testing::cosim_options;

NormalEncoderBlock make_block(const EncoderConfig& config = {}) {
  BlockOptions o;
  o.encoder = config;
  return NormalEncoderBlock(o);
}

EncoderConfig linear_index() {
  EncoderConfig c;
  c.lut_exp = 1;
  c.lut_mant = 7;
  return c;
}

void expect_every_case_hit(const CosimResult& r) {
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

// The default encoder: the directed cases and a million random normals through the rtl (twice,
// for the X check), 20000 through the hls model, under back-pressure; every case hit.
TEST(NormalEncoderCosimTest, GoldenVsHlsVsRtl) {
  const NormalEncoderBlock block = make_block();
  {
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(20260101, 1'000'000, {"rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    expect_every_case_hit(r);
    std::cout << log.str().substr(log.str().find("coverage:"));
  }
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(17, 20'000, {"hls", "rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  expect_every_case_hit(r);
}

TEST(NormalEncoderCosimTest, HeavyBackPressure) {
  const NormalEncoderBlock block = make_block();
  CosimOptions o = options(7, 20'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
}

// One normal per clock: without bubbles or stalls the rtl takes the items, its latency (8
// cycles) and the harness's 16 drain cycles.
TEST(NormalEncoderCosimTest, OneNormalPerClock) {
  const NormalEncoderBlock block = make_block();
  CosimOptions o = options(3, 20'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  EXPECT_LE(r.runs.at("rtl").cycles, r.items + 8 + 16) << log.str();
  EXPECT_LE(r.runs.at("hls").cycles, r.items + 8 + 16) << log.str();
}

// The directed items alone reach every angle-table index a ratio can reach, for phi and for
// theta, and every seed-table index of both dividers. With E > 1 the first E - 1 levels'
// entries of m < 2^(M-2) are dead (the leading pair is never zero there): 104 of the default's
// 128 entries are reachable; the linear index reaches all 128.
TEST(NormalEncoderCosimTest, DirectedItemsReachEveryTableIndex) {
  for (const EncoderConfig& c : {EncoderConfig{}, linear_index()}) {
    const NormalEncoderBlock block = make_block(c);
    const std::set<uint32_t> reachable = reachable_angle_indices(c);
    EXPECT_EQ(reachable.size(), c.lut_exp == 1 ? 128u : 104u);
    const deflect::NormalEncoder enc(c);
    std::set<uint32_t> angle[2], seed[2];
    for (const Txn& item : block.directed_items()) {
      deflect::EncoderTrace t;
      const int16_t x = normal_x(item), y = normal_y(item), z = normal_z(item);
      enc.encode(x, y, z, &t);
      if (t.t_phi != 0) angle[0].insert(deflect::angle_index(c, t.t_phi));  // t = 0: no read
      if (t.t_theta != 0) angle[1].insert(deflect::angle_index(c, t.t_theta));
      const auto sq = [](int16_t v) { return static_cast<uint32_t>(int32_t{v} * int32_t{v}); };
      seed[0].insert(encoder_seed_index(std::max(sq(x), sq(z)), c.seed_bits));
      seed[1].insert(encoder_seed_index(std::max(sq(y), sq(x) + sq(z)), c.seed_bits));
    }
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(angle[k], reachable) << (k ? "theta" : "phi");
      EXPECT_EQ(seed[k].size(), size_t{1} << c.seed_bits) << (k ? "theta" : "phi");
    }
  }
}

// The paper's linear index (E = 1, M = 7), verilated as Vtmu_normal_encoder_e1m7.
TEST(NormalEncoderCosimTest, LinearIndexVariant) {
  const NormalEncoderBlock block = make_block(linear_index());
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(23, 50'000, {"hls", "rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  expect_every_case_hit(r);
}

// The extreme widths (S = 12, E = 8, M = 10, S = 2 with E = 2) through the hls model: the
// directed generator still reaches every reachable index.
TEST(NormalEncoderCosimTest, ExtremeWidthsGoldenVsHls) {
  EncoderConfig wide;
  wide.seed_bits = 12;
  wide.lut_exp = 8;
  wide.lut_mant = 10;
  EncoderConfig narrow;
  narrow.seed_bits = 2;
  narrow.lut_exp = 2;
  narrow.lut_mant = 2;
  for (const EncoderConfig& c : {wide, narrow}) {
    const NormalEncoderBlock block = make_block(c);
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(29, 5'000, {"hls"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    expect_every_case_hit(r);
  }
}

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(uint64_t seed, size_t count, std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.x_check = false;
  return run_cosim(make_block(), o, log, [](const std::string& level) -> std::unique_ptr<Engine> {
    if (level != "rtl") return nullptr;
    return make_normal_encoder_rtl_engine<Model>("rtl");
  });
}

// The Newton-Raphson step drops r1's last bit: t is one LSB low for a third of the ratios,
// but the table hides it unless t sits on a bucket's first value (about 1 random unit normal
// in 4300 shows it): the directed bucket-edge ratios alone catch it.
TEST(NormalEncoderCosimTest, NewtonRaphsonMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_normal_encoder_mutant_nr>(9, 0, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim normal-encoder --seed 9");
}

// Theta does not saturate at the poles: the directed poles alone catch it.
TEST(NormalEncoderCosimTest, PoleMutantIsCaughtByTheDirectedCases) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_normal_encoder_mutant_pole>(9, 0, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

TEST(NormalEncoderCosimTest, InjectedFaultFailsTheRun) {
  CosimOptions o = options(5, 1000, {"hls", "rtl"});
  o.inject_fault = 500;
  std::stringstream log;
  const CosimResult r = run_cosim(make_block(), o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 500"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace tmu::tb
