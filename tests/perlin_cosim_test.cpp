// The procedural noise hardware (002 §4.1): the noise unit (`perlin`) and the fractal sums of
// four octaves (`turbulence`) in both configurations, pipelined (four noise units) and shared
// (one noise unit, the thesis's four clocks per sample): golden vs hls vs rtl, bit for bit, on
// the blocks' directed hard cases (lattice points, cell boundaries, every fade index, negative
// and extreme coordinates, octave shifts beyond 24 bits, u = v = w) and random coordinates
// under back-pressure; the throughput of each configuration on simulated cycles; the X-initial
// check; the octave shift's 24-bit wrap against golden's 64-bit multiplication; and proof that
// the comparison has teeth (RTL mutants: the hash's second add of w dropped, the fade table
// truncated, |-1.0| wrong, the octave shift off by one, the shared controller one octave
// early; an injected wrong bit).
#include <Vtmu_fractal_pipelined_mutant_abs.h>
#include <Vtmu_fractal_pipelined_mutant_octave.h>
#include <Vtmu_fractal_shared_mutant_abs.h>
#include <Vtmu_fractal_shared_mutant_early.h>
#include <Vtmu_noise_mutant_fade.h>
#include <Vtmu_noise_mutant_hash.h>
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <sstream>

#include "blocks/perlin_block.hpp"
#include "harness/cosim.hpp"
#include "perlin/noise.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

constexpr auto options = testing::cosim_options;
using perlin::NoiseConfig;

TurbulenceBlock turbulence_block(bool shared) {
  BlockOptions o;
  o.fractal_shared = shared;
  return TurbulenceBlock(o);
}

void expect_every_case_hit(const CosimResult& r) {
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

// The coverage of the directed items alone (golden only, no engine compared).
CosimResult directed_only(const Block& block) {
  CosimOptions o = options(1, 0, {});
  std::stringstream log;
  return run_cosim(block, o, log);
}

// --- the stimulus and the spec ------------------------------------------------------------

// The block's trace of the noise is golden's noise.
TEST(PerlinBlockTest, TraceIsTheGoldenNoise) {
  std::mt19937_64 rng(5);
  std::vector<Txn> items = noise_directed_items();
  for (const Txn& t : noise_random_items(rng, 20000)) items.push_back(t);
  for (const Txn& t : items) {
    const auto [u, v, w] = solid_coords(t);
    ASSERT_EQ(trace_noise(u, v, w).p, perlin::noise(NoiseConfig{}, u, v, w))
        << u << " " << v << " " << w;
  }
}

// The RTL's octave i shifts the 24-bit raw coordinates left by i and wraps them; golden
// multiplies in 64 bits. The noise reads only the low 24 bits (the lattice index mod 2^12 and
// the fraction), so both give the same noise: checked on every directed item and 200000
// random ones, whose octave shifts overflow 24 bits often.
TEST(PerlinBlockTest, OctaveShiftWrappedTo24BitsIsGoldensOctave) {
  std::mt19937_64 rng(6);
  std::vector<Txn> items = turbulence_block(false).directed_items();
  for (const Txn& t : noise_random_items(rng, 200000)) items.push_back(t);
  size_t wrapped = 0;
  const auto wrap24 = [](int64_t x) {
    return static_cast<int64_t>(static_cast<int32_t>(static_cast<uint32_t>(x) << 8) >> 8);
  };
  for (const Txn& t : items) {
    const auto c = solid_coords(t);
    for (int i = 1; i < perlin::kOctaves; ++i) {
      const int64_t s = int64_t{1} << i;
      const int64_t u = c[0] * s, v = c[1] * s, w = c[2] * s;
      if (wrap24(u) != u || wrap24(v) != v || wrap24(w) != w) ++wrapped;
      ASSERT_EQ(perlin::noise(NoiseConfig{}, u, v, w),
                perlin::noise(NoiseConfig{}, wrap24(u), wrap24(v), wrap24(w)))
          << c[0] << " " << c[1] << " " << c[2] << " octave " << i;
    }
  }
  EXPECT_GT(wrapped, items.size() / 10);
}

// The directed items alone hit every coverage case of both blocks.
TEST(PerlinBlockTest, DirectedItemsHitEveryCase) {
  expect_every_case_hit(directed_only(PerlinBlock()));
  expect_every_case_hit(directed_only(turbulence_block(false)));
}

// --- perlin: the noise unit ---------------------------------------------------------------

// The directed cases and a million random coordinates through the rtl (twice, for the X
// check), 20000 through the hls model, under back-pressure; every case hit.
TEST(PerlinCosimTest, GoldenVsHlsVsRtl) {
  const PerlinBlock block;
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

// Random coordinates alone (no directed items) hit every case too: P = -1.0 among them (a
// lattice point of value -1.0: 1 in 256 of the random lattice points).
TEST(PerlinCosimTest, RandomItemsAlone) {
  CosimOptions o = options(31, 200'000, {"rtl"});
  o.directed = false;
  std::stringstream log;
  const CosimResult r = run_cosim(PerlinBlock(), o, log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

TEST(PerlinCosimTest, HeavyBackPressure) {
  CosimOptions o = options(7, 20'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(PerlinBlock(), o, log).pass) << log.str();
}

// The output never ready for long stretches: the pipeline holds, drops nothing.
TEST(PerlinCosimTest, OutputMostlyStalled) {
  CosimOptions o = options(8, 5'000, {"hls", "rtl"});
  o.directed = false;
  o.in_idle = 0.0;
  o.out_stall = 0.95;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(PerlinBlock(), o, log).pass) << log.str();
}

// One sample per clock: without bubbles or stalls the rtl takes the items, its latency (7
// cycles) and the harness's 16 drain cycles.
TEST(PerlinCosimTest, OneSamplePerClock) {
  CosimOptions o = options(3, 20'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(PerlinBlock(), o, log);
  ASSERT_TRUE(r.pass) << log.str();
  EXPECT_LE(r.runs.at("rtl").cycles, r.items + 7 + 16) << log.str();
  EXPECT_LE(r.runs.at("hls").cycles, r.items + 7 + 16) << log.str();
}

// X: the rtl run repeated with other random initial values of every flop gives the same
// outputs on the same cycles (the data registers have no reset; only the valids do).
TEST(PerlinCosimTest, RandomInitialValuesDoNotLeak) {
  CosimOptions o = options(11, 20'000, {"rtl"});
  ASSERT_TRUE(o.x_check);
  std::stringstream log;
  const CosimResult r = run_cosim(PerlinBlock(), o, log);
  EXPECT_TRUE(r.pass) << log.str();
  EXPECT_NE(log.str().find("x-check  rtl with random initial values"), std::string::npos)
      << log.str();
  EXPECT_NE(log.str().find(": identical"), std::string::npos) << log.str();
}

// The worked examples of rtl/perlin/tmu_noise.sv's header through every engine.
TEST(PerlinCosimTest, HeaderExamples) {
  const PerlinBlock block;
  const std::vector<Txn> items = {solid_item(0, 0, 0), solid_item(0x800, 0, 0)};
  const int32_t r0 = perlin::lattice_value(0, 0, 0), r1 = perlin::lattice_value(1, 0, 0);
  EXPECT_EQ(r0, 0);
  // c_u = 128: P = r0 16 + round(128 (r1 - r0) 16 / 256) = 8 (r0 + r1), exact.
  const auto want = static_cast<uint64_t>(8 * (r0 + r1)) & 0xFFFu;
  for (const std::string level : {"golden", "hls", "rtl"}) {
    const RunResult r = block.engine(level)->run(items, RunOptions{});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs.size(), 2u) << level;
    EXPECT_EQ(r.outputs[0].f[kPerlinP], 0u) << level;
    EXPECT_EQ(r.outputs[1].f[kPerlinP], want) << level;
  }
}

// --- turbulence: both configurations ------------------------------------------------------

class TurbulenceCosimTest : public ::testing::TestWithParam<bool> {};

// The directed cases and 200000 random coordinates through the rtl (twice, for the X check),
// 20000 through the hls model, under back-pressure; every case hit.
TEST_P(TurbulenceCosimTest, GoldenVsHlsVsRtl) {
  const TurbulenceBlock block = turbulence_block(GetParam());
  {
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(20260101, 200'000, {"rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    expect_every_case_hit(r);
    std::cout << log.str().substr(log.str().find("coverage:"));
  }
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(17, 20'000, {"hls", "rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  expect_every_case_hit(r);
}

TEST_P(TurbulenceCosimTest, HeavyBackPressure) {
  CosimOptions o = options(7, 10'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(turbulence_block(GetParam()), o, log).pass) << log.str();
}

TEST_P(TurbulenceCosimTest, OutputMostlyStalled) {
  CosimOptions o = options(8, 3'000, {"hls", "rtl"});
  o.directed = false;
  o.in_idle = 0.0;
  o.out_stall = 0.95;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(turbulence_block(GetParam()), o, log).pass) << log.str();
}

TEST_P(TurbulenceCosimTest, RandomInitialValuesDoNotLeak) {
  CosimOptions o = options(11, 10'000, {"rtl"});
  ASSERT_TRUE(o.x_check);
  std::stringstream log;
  const CosimResult r = run_cosim(turbulence_block(GetParam()), o, log);
  EXPECT_TRUE(r.pass) << log.str();
  EXPECT_NE(log.str().find(": identical"), std::string::npos) << log.str();
}

// The throughput, on simulated cycles without bubbles or stalls: pipelined one sample per
// clock (the items, the latency of 8 and the 16 drain cycles); shared one per 4 clocks (the
// thesis: "four cycles are needed to create one fractal value"), the hls model as the rtl.
TEST_P(TurbulenceCosimTest, CyclesPerSample) {
  const bool shared = GetParam();
  CosimOptions o = options(3, 20'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(turbulence_block(shared), o, log);
  ASSERT_TRUE(r.pass) << log.str();
  const uint64_t n = r.items;
  for (const std::string level : {"rtl", "hls"}) {
    const uint64_t cycles = r.runs.at(level).cycles;
    const double per_sample = static_cast<double>(cycles) / static_cast<double>(n);
    std::cout << level << (shared ? " shared" : " pipelined") << ": " << cycles << " cycles, " << n
              << " samples, " << per_sample << " cycles per sample\n";
    if (shared) {
      EXPECT_GE(cycles, 4 * n - 3) << level;        // never faster than 4 clocks
      EXPECT_LE(cycles, 4 * n + 12 + 16) << level;  // latency 12, drain 16
      EXPECT_NEAR(per_sample, 4.0, 0.01) << level;
    } else {
      EXPECT_LE(cycles, n + 8 + 16) << level;
      EXPECT_NEAR(per_sample, 1.0, 0.01) << level;
    }
  }
  // The report shows it.
  EXPECT_NE(log.str().find(shared ? "4.00/txn" : "1.00/txn"), std::string::npos) << log.str();
}

INSTANTIATE_TEST_SUITE_P(Configurations, TurbulenceCosimTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return std::string(param.param ? "Shared" : "Pipelined");
                         });

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_perlin_mutant(uint64_t seed, size_t count, bool directed, std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.directed = directed;
  o.x_check = false;
  return run_cosim(PerlinBlock(), o, log, [](const std::string& level) -> std::unique_ptr<Engine> {
    if (level != "rtl") return nullptr;
    return make_perlin_rtl_engine<Model>("rtl");
  });
}

template <class Model>
CosimResult run_turbulence_mutant(bool shared, uint64_t seed, size_t count, bool directed,
                                  std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.directed = directed;
  o.x_check = false;
  return run_cosim(turbulence_block(shared), o, log,
                   [](const std::string& level) -> std::unique_ptr<Engine> {
                     if (level != "rtl") return nullptr;
                     return make_turbulence_rtl_engine<Model>("rtl");
                   });
}

// The hash drops the second add of w: every item but the ones whose eight corners happen to
// agree differs.
TEST(PerlinMutantTest, HashMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_perlin_mutant<Vtmu_noise_mutant_hash>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim perlin --seed 9");
}

// The fade table truncates: the directed sweep of every fade index catches it.
TEST(PerlinMutantTest, FadeMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_perlin_mutant<Vtmu_noise_mutant_fade>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim perlin --seed 9");
}

// ... and random coordinates alone catch both noise mutants too.
TEST(PerlinMutantTest, MutantsAreCaughtByRandomItemsAlone) {
  {
    std::stringstream log;
    EXPECT_FALSE((run_perlin_mutant<Vtmu_noise_mutant_hash>(5, 2000, false, log).pass));
    EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
  }
  std::stringstream log;
  EXPECT_FALSE((run_perlin_mutant<Vtmu_noise_mutant_fade>(5, 2000, false, log).pass));
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

// |-1.0| read as a signed value: only P = -1.0 shows it, which the directed lattice points of
// value -1.0 (one per octave) reach.
TEST(PerlinMutantTest, PipelinedAbsMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r =
      run_turbulence_mutant<Vtmu_fractal_pipelined_mutant_abs>(false, 9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim turbulence --seed 9");
}

TEST(PerlinMutantTest, PipelinedOctaveMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r =
      run_turbulence_mutant<Vtmu_fractal_pipelined_mutant_octave>(false, 9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim turbulence --seed 9");
}

TEST(PerlinMutantTest, SharedAbsMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r =
      run_turbulence_mutant<Vtmu_fractal_shared_mutant_abs>(true, 9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim turbulence --seed 9");
  EXPECT_NE(log.str().find("--fractal shared --engines rtl"), std::string::npos) << log.str();
}

// The controller takes the next sample one octave early: the octaves fall out of step with
// the accumulator (and a sample's output goes missing).
TEST(PerlinMutantTest, SharedEarlyMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r =
      run_turbulence_mutant<Vtmu_fractal_shared_mutant_early>(true, 9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim turbulence --seed 9");
}

TEST(PerlinMutantTest, InjectedFaultFailsTheRun) {
  for (const bool shared : {false, true}) {
    CosimOptions o = options(5, 1000, {"hls", "rtl"});
    o.directed = false;
    o.inject_fault = 500;
    std::stringstream log;
    const CosimResult r = run_cosim(turbulence_block(shared), o, log);
    EXPECT_FALSE(r.pass);
    EXPECT_NE(log.str().find("first at transaction 500"), std::string::npos) << log.str();
  }
}

}  // namespace
}  // namespace tmu::tb
