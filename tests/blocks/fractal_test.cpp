// What is the fractal sums' own (002 §4.1.1; the conformance suite checks what every block
// shares): the RTL's 24-bit octave shift gives golden's noise, and each configuration's rate,
// one sample per clock pipelined and one per 4 clocks shared, in rtl and hls.
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <sstream>

#include "blocks/fractal/fractal_block.hpp"
#include "blocks/noise/solid_stimulus.hpp"
#include "harness/cosim.hpp"
#include "perlin/noise.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using perlin::NoiseConfig;

FractalBlock fractal_block(bool shared) {
  BlockOptions o;
  o.fractal_shared = shared;
  return FractalBlock(o);
}

// The RTL's octave i shifts the 24-bit raw coordinates left by i and wraps them; golden
// multiplies in 64 bits. The noise reads only the low 24 bits (the lattice index mod 2^12 and
// the fraction), so both give the same noise: checked on every directed item and 200000
// random ones, whose octave shifts overflow 24 bits often.
TEST(FractalTest, OctaveShiftWrappedTo24BitsIsGoldensOctave) {
  std::mt19937_64 rng(6);
  std::vector<Txn> items = fractal_block(false).directed_items();
  for (const Txn& t : solid::random_items(rng, 200000)) items.push_back(t);
  size_t wrapped = 0;
  for (const Txn& t : items) {
    const auto c = solid::coords(t);
    for (int i = 1; i < perlin::kOctaves; ++i) {
      const int64_t s = int64_t{1} << i;
      const int64_t u = c[0] * s, v = c[1] * s, w = c[2] * s;
      if (solid::wrap24(u) != u || solid::wrap24(v) != v || solid::wrap24(w) != w) ++wrapped;
      ASSERT_EQ(perlin::noise(NoiseConfig{}, u, v, w),
                perlin::noise(NoiseConfig{}, solid::wrap24(u), solid::wrap24(v), solid::wrap24(w)))
          << c[0] << " " << c[1] << " " << c[2] << " octave " << i;
    }
  }
  EXPECT_GT(wrapped, items.size() / 10);
}

class FractalRateTest : public ::testing::TestWithParam<bool> {};

// The throughput, on simulated cycles without bubbles or stalls: pipelined one sample per
// clock (the items, the latency of 8 and the 16 drain cycles); shared one per 4 clocks (the
// thesis: "four cycles are needed to create one fractal value"), the hls model as the rtl.
TEST_P(FractalRateTest, CyclesPerSample) {
  const bool shared = GetParam();
  CosimOptions o = testing::cosim_options(3, 20'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(fractal_block(shared), o, log);
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

INSTANTIATE_TEST_SUITE_P(Configurations, FractalRateTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return std::string(param.param ? "Shared" : "Pipelined");
                         });

}  // namespace
}  // namespace tmu::tb
