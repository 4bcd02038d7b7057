// What is the footprint setup's own (000 §10; the conformance suite checks what every block
// shares): the RTL header's worked example, and one fragment per clock with its plan 7 cycles
// after the request.
#include <gtest/gtest.h>

#include <iostream>

#include "blocks/footprint_setup/footprint_setup_block.hpp"
#include "harness/handshake_driver.hpp"

namespace tmu::tb {
namespace {

using D = desc::footprint_setup;
constexpr int32_t kOne = 256;

footprint::Config heights(int log2_max_probes) {
  footprint::Config c;
  c.log2_max_probes = log2_max_probes;
  c.q_rule = footprint::QRule::kHeights;
  return c;
}

// tmu_footprint_setup.sv's example (D 12, T 7, F 8, heights, at most 16 probes): r1 = (8, 0),
// r2 = (0, 1) texels: k = 3 (8 probes along r1), lambda = max(log2 q = 0, 3 - 3) = 0; the
// centre and shade pass through.
TEST(FootprintSetupTest, TheHeadersExample) {
  const FootprintSetupBlock block(BlockOptions{});
  const std::vector<Txn> items = {FootprintSetupBlock::config_item(heights(4)),
                                  FootprintSetupBlock::fragment_item(
                                      {10 * kOne, 20 * kOne, 8 * kOne, 0, 0, kOne, 0x11223344u})};
  for (const std::string level : {"golden", "rtl"}) {
    const RunResult r = block.engine(level)->run(items, {});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs.size(), 1u) << level;
    const Txn& p = r.outputs[0];
    EXPECT_EQ(p.f[D::plan_log2_n], 3u) << level;
    EXPECT_EQ(p.f[D::plan_lambda], 0u) << level;
    EXPECT_EQ(p.f[D::plan_du], uint64_t{8 * kOne}) << level;
    EXPECT_EQ(p.f[D::plan_dv], 0u) << level;
    EXPECT_EQ(p.f[D::plan_u], uint64_t{10 * kOne}) << level;
    EXPECT_EQ(p.f[D::plan_v], uint64_t{20 * kOne}) << level;
    EXPECT_EQ(p.f[D::plan_shade], 0x11223344u) << level;
  }
}

// Back-to-back fragments, the plan always taken: one per clock, the first plan 7 cycles after
// its request.
TEST(FootprintSetupTest, OneFragmentPerClock) {
  const FootprintSetupBlock block(BlockOptions{});
  std::vector<Txn> items = {FootprintSetupBlock::config_item(heights(4))};
  constexpr int kFragments = 1000;
  for (int i = 0; i < kFragments; ++i) {
    items.push_back(FootprintSetupBlock::fragment_item(
        {i * kOne, kOne, (i % 64 + 1) * kOne, i % 7, -(i % 5), kOne, uint32_t(i)}));
  }
  const RunResult r = block.engine("rtl")->run(items, {});
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_EQ(r.output_cycles.size(), size_t{kFragments});
  // The configuration is written after the quiet cycles, the first fragment taken the cycle
  // after it.
  const uint64_t first_request = kQuietCycles + 1;
  EXPECT_EQ(r.output_cycles.front(), first_request + 7);
  EXPECT_EQ(r.output_cycles.back() - r.output_cycles.front(), uint64_t{kFragments - 1});
  std::cout << kFragments << " fragments, outputs at cycles " << r.output_cycles.front() << ".."
            << r.output_cycles.back() << "\n";
}

}  // namespace
}  // namespace tmu::tb
