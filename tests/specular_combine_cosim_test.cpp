// The specular combine (000 §7 eq. 6, §8 eq. 7): the golden rule against a plain double
// reference for every (e, r) pair and every d; golden vs hls vs rtl, bit for bit, on the
// block's directed cases (zero and full reflectance, E = 0 and 255, each channel alone at the
// saturation edge, alpha passthrough, every (e, r) pair in every channel) and random colours
// under back-pressure; one colour per clock; the X-initial check; and proof that the
// comparison has teeth (RTL mutants: the sum wrapping instead of saturating, alpha from E; an
// injected wrong bit).
#include <Vtmu_specular_combine_mutant_alpha.h>
#include <Vtmu_specular_combine_mutant_wrap.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "blocks/specular_combine_block.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"
#include "texram/specular_combine.hpp"

namespace tmu::tb {
namespace {

constexpr auto options = testing::cosim_options;

// The worked example of rtl/texram/tmu_specular_combine.sv's header, at compile time.
static_assert(texram::specular_combine(0xF0804020u, 0x80FF40FFu, 0x40FFFF00u) == 0xFFFF8020u);
static_assert(texram::specular_combine(0x12345678u, 0xFFFFFFFFu, 0x000000FFu) == 0x12345678u);

void expect_every_case_hit(const CosimResult& r) {
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

// min(255, d + round(e r / 255)) in double precision.
uint32_t reference(uint32_t d, uint32_t e, uint32_t r) {
  const double sum = d + std::round(static_cast<double>(e) * r / 255.0);
  return static_cast<uint32_t>(std::min(255.0, sum));
}

// The golden rule against the double reference for every e, r and d (2^24 triples), each
// triple in R, in G (with e, r swapped) and in B (with d mirrored), and the alpha from D
// whatever E's and R's alphas are.
TEST(SpecularCombineGoldenTest, EveryTripleMatchesTheDoubleReference) {
  uint64_t failures = 0;
  for (uint32_t e = 0; e < 256; ++e) {
    for (uint32_t r = 0; r < 256; ++r) {
      // mul255 itself: e r / 255 is never exactly half way (255 is odd).
      ASSERT_EQ(texram::mul255(e, r), static_cast<uint32_t>(std::lround(e * r / 255.0)))
          << "e " << e << " r " << r;
      for (uint32_t d = 0; d < 256; ++d) {
        const uint32_t alpha = (d + e + r) & 0xFFu;
        const uint32_t dw = d << 24 | d << 16 | (255 - d) << 8 | alpha;
        const uint32_t ew = e << 24 | r << 16 | e << 8 | (~alpha & 0xFFu);
        const uint32_t rw = r << 24 | e << 16 | r << 8 | (alpha ^ 0x5Au);
        const uint32_t want = reference(d, e, r) << 24 | reference(d, r, e) << 16 |
                              reference(255 - d, e, r) << 8 | alpha;
        const uint32_t got = texram::specular_combine(dw, ew, rw);
        if (got != want && ++failures <= 10) {
          ADD_FAILURE() << std::hex << "d " << d << " e " << e << " r " << r << ": got 0x" << got
                        << ", want 0x" << want;
        }
      }
    }
  }
  EXPECT_EQ(failures, 0u);
}

// The directed cases (every (e, r) pair in every channel among them) and a million random
// colours through the rtl (twice, for the X check), 50000 through the hls model, under
// back-pressure; every case hit.
TEST(SpecularCombineCosimTest, GoldenVsHlsVsRtl) {
  const SpecularCombineBlock block;
  {
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(20260101, 1'000'000, {"rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    expect_every_case_hit(r);
    std::cout << log.str().substr(log.str().find("coverage:"));
  }
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(17, 50'000, {"hls", "rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  expect_every_case_hit(r);
}

// Random colours alone (no directed items) hit every case but the exhaustive pair sweeps.
TEST(SpecularCombineCosimTest, RandomItemsAlone) {
  const SpecularCombineBlock block;
  CosimOptions o = options(31, 200'000, {"hls", "rtl"});
  o.directed = false;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const auto& [name, n] : r.coverage) {
    if (name.find("every (e, r) pair") == std::string::npos) {
      EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
    }
  }
}

TEST(SpecularCombineCosimTest, HeavyBackPressure) {
  const SpecularCombineBlock block;
  CosimOptions o = options(7, 20'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
}

// The output never ready for long stretches: the pipeline holds, drops nothing.
TEST(SpecularCombineCosimTest, OutputMostlyStalled) {
  const SpecularCombineBlock block;
  CosimOptions o = options(8, 5'000, {"hls", "rtl"});
  o.directed = false;
  o.in_idle = 0.0;
  o.out_stall = 0.95;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
}

// One colour per clock: without bubbles or stalls the rtl takes the items, its latency (2
// cycles) and the harness's 16 drain cycles.
TEST(SpecularCombineCosimTest, OneColourPerClock) {
  const SpecularCombineBlock block;
  CosimOptions o = options(3, 20'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  EXPECT_LE(r.runs.at("rtl").cycles, r.items + 2 + 16) << log.str();
  EXPECT_LE(r.runs.at("hls").cycles, r.items + 2 + 16) << log.str();
}

// X: the rtl run repeated with other random initial values of every flop gives the same
// outputs on the same cycles (the data registers have no reset; only the valids do).
TEST(SpecularCombineCosimTest, RandomInitialValuesDoNotLeak) {
  const SpecularCombineBlock block;
  CosimOptions o = options(11, 20'000, {"rtl"});
  ASSERT_TRUE(o.x_check);
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_TRUE(r.pass) << log.str();
  EXPECT_NE(log.str().find("x-check  rtl with random initial values"), std::string::npos)
      << log.str();
  EXPECT_NE(log.str().find(": identical"), std::string::npos) << log.str();
}

// The items a renderer builds with specular_combine_item come out as the golden rule says.
TEST(SpecularCombineCosimTest, ItemHelperFeedsTheEngines) {
  const SpecularCombineBlock block;
  const std::vector<Txn> items = {specular_combine_item(0xF0804020u, 0x80FF40FFu, 0x40FFFF00u),
                                  specular_combine_item(0x10203040u, 0xFFFFFFFFu, 0xFFFFFF00u)};
  for (const std::string level : {"golden", "hls", "rtl"}) {
    const RunResult r = block.engine(level)->run(items, RunOptions{});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs.size(), 2u) << level;
    EXPECT_EQ(r.outputs[0].f[kSpcColour], 0xFFFF8020u) << level;
    EXPECT_EQ(r.outputs[1].f[kSpcColour], 0xFFFFFF40u) << level;
  }
}

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(uint64_t seed, size_t count, bool directed, std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.directed = directed;
  o.x_check = false;
  return run_cosim(SpecularCombineBlock(), o, log,
                   [](const std::string& level) -> std::unique_ptr<Engine> {
                     if (level != "rtl") return nullptr;
                     return make_specular_combine_rtl_engine<Model>("rtl");
                   });
}

// The sum wraps instead of saturating at 255: the directed saturation edge catches it (and
// the assertion that no channel darkens fires).
TEST(SpecularCombineCosimTest, WrapMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_specular_combine_mutant_wrap>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim specular-combine --seed 9");
}

// C's alpha is E's: the directed alpha passthrough cases catch it ...
TEST(SpecularCombineCosimTest, AlphaMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_specular_combine_mutant_alpha>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim specular-combine --seed 9");
}

// ... and random colours alone catch both mutants too.
TEST(SpecularCombineCosimTest, MutantsAreCaughtByRandomItemsAlone) {
  {
    std::stringstream log;
    EXPECT_FALSE((run_mutant<Vtmu_specular_combine_mutant_wrap>(5, 2000, false, log).pass));
    EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
  }
  std::stringstream log;
  EXPECT_FALSE((run_mutant<Vtmu_specular_combine_mutant_alpha>(5, 2000, false, log).pass));
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

TEST(SpecularCombineCosimTest, InjectedFaultFailsTheRun) {
  CosimOptions o = options(5, 1000, {"hls", "rtl"});
  o.directed = false;
  o.inject_fault = 500;
  std::stringstream log;
  const CosimResult r = run_cosim(SpecularCombineBlock(), o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 500"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace tmu::tb
