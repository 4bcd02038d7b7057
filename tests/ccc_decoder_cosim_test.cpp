// CCC decoder: golden vs hls vs rtl, bit for bit, and proof that the comparison has teeth.
#include <Vtmu_ccc_decoder_mutant.h>
#include <Vtmu_ccc_decoder_mutant_stall.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "blocks/ccc_decoder_block.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

constexpr auto options = testing::cosim_options;

TEST(CccDecoderCosimTest, MillionRandomTransactionsGoldenVsRtl) {
  const uint64_t seed = 20261122;
  std::cout << "seed " << seed << "\n";
  const CccDecoderBlock block(seed);
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(seed, 1'000'000, {"rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  EXPECT_GE(r.transactions, 980'000u);  // 1 in 64 items is a CLUT write, not a decode
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

TEST(CccDecoderCosimTest, GoldenVsHlsVsRtlUnderHeavyBackPressure) {
  const CccDecoderBlock block(7);
  CosimOptions o = options(7, 50'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
}

TEST(CccDecoderCosimTest, FullThroughputWithoutStalls) {
  const CccDecoderBlock block(3);
  CosimOptions o = options(3, 10'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  // One texel per clock: every item (decode or CLUT write) takes one cycle, plus the drain.
  EXPECT_LE(r.runs.at("rtl").cycles, r.items + 20) << log.str();
  EXPECT_LE(r.runs.at("hls").cycles, r.items + 20) << log.str();
}

// The teeth: a flipped bit in the results, and an RTL with a real bug, must both fail.
TEST(CccDecoderCosimTest, InjectedFaultFailsTheRun) {
  const CccDecoderBlock block(5);
  CosimOptions o = options(5, 1000, {"hls", "rtl"});
  o.inject_fault = 500;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 500"), std::string::npos) << log.str();
}

TEST(CccDecoderCosimTest, MutantRtlIsCaughtWithAWaveform) {
  const CccDecoderBlock block(9);
  CosimOptions o = options(9, 2000, {"rtl"});
  std::filesystem::remove_all(o.wave_dir);
  std::stringstream log;
  const CosimResult r =
      run_cosim(block, o, log, [](const std::string& level) -> std::unique_ptr<Engine> {
        if (level == "rtl") return make_ccc_decoder_rtl_engine<Vtmu_ccc_decoder_mutant>("rtl");
        return nullptr;
      });
  EXPECT_FALSE(r.pass);
  EXPECT_EQ(r.failing_engine, "rtl");
  EXPECT_NE(log.str().find("reproduce: texsim cosim ccc --seed 9"), std::string::npos) << log.str();
  ASSERT_FALSE(r.wave_path.empty());
  EXPECT_GT(std::filesystem::file_size(r.wave_path), 0u);
  EXPECT_TRUE(std::filesystem::exists(r.wave_path.substr(0, r.wave_path.size() - 4) + ".gtkw"));
}

// An RTL assertion that fires fails the run (with the cycle) instead of aborting the process.
TEST(CccDecoderCosimTest, FiredAssertionFailsTheRun) {
  const CccDecoderBlock block(4);
  CosimOptions o = options(4, 2000, {"rtl"});
  o.out_stall = 0.5;
  std::stringstream log;
  const CosimResult r =
      run_cosim(block, o, log, [](const std::string& level) -> std::unique_ptr<Engine> {
        if (level == "rtl")
          return make_ccc_decoder_rtl_engine<Vtmu_ccc_decoder_mutant_stall>("rtl");
        return nullptr;
      });
  EXPECT_FALSE(r.pass);
  EXPECT_NE(r.runs.at("rtl").error.find("RTL assertion failed at cycle"), std::string::npos)
      << log.str();
}

}  // namespace
}  // namespace tmu::tb
