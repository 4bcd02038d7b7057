// What is the noise unit's own (002 §4.1; the conformance suite, tests/conformance_test.cpp,
// checks what every block shares): the block's trace of the noise is golden's noise, the worked
// examples of rtl/perlin/tmu_noise.sv's header through every engine, one sample per clock.
#include "perlin/noise.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "blocks/noise/noise_block.hpp"
#include "blocks/noise/solid_stimulus.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using perlin::NoiseConfig;

// The coverage predicates read the noise through trace_noise: it must be golden's noise.
TEST(NoiseTest, TraceIsTheGoldenNoise) {
  std::mt19937_64 rng(5);
  std::vector<Txn> items = solid::directed_items();
  for (const Txn& t : solid::random_items(rng, 20000)) items.push_back(t);
  for (const Txn& t : items) {
    const auto [u, v, w] = solid::coords(t);
    ASSERT_EQ(trace_noise(u, v, w).p, perlin::noise(NoiseConfig{}, u, v, w))
        << u << " " << v << " " << w;
  }
}

// The worked examples of rtl/perlin/tmu_noise.sv's header through every engine.
TEST(NoiseTest, HeaderExamples) {
  const NoiseBlock block;
  const std::vector<Txn> items = {solid::item(0, 0, 0), solid::item(0x800, 0, 0)};
  const int32_t r0 = perlin::lattice_value(0, 0, 0), r1 = perlin::lattice_value(1, 0, 0);
  EXPECT_EQ(r0, 0);
  // c_u = 128: P = r0 16 + round(128 (r1 - r0) 16 / 256) = 8 (r0 + r1), exact.
  const auto want = static_cast<uint64_t>(8 * (r0 + r1)) & 0xFFFu;
  testing::expect_outputs(block, items, desc::noise::out_p, {0u, want});
}

// One sample per clock: without bubbles or stalls the rtl takes the items, its latency (7
// cycles) and the harness's 16 drain cycles; the hls model keeps the same rate.
TEST(NoiseTest, OneSamplePerClock) {
  testing::expect_full_rate(NoiseBlock(), 20'000, {{"rtl", 7 + 16}, {"hls", 7 + 16}});
}

}  // namespace
}  // namespace tmu::tb
