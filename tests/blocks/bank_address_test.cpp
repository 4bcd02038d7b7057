// What is the TEXRAM bank address unit's own (000 §2, Fig. 2; the conformance suite checks what
// every block shares): the rtl equals Geometry::cell on every layout the TEXRAM holds (every
// texture size, texel and block grids, one and four planes, every level: every stored position
// of the small levels, the corners and 256 random positions of the larger ones), and a position
// outside the layout is a stimulus error golden reports.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "blocks/bank_address/bank_address_block.hpp"
#include "formats/formats.hpp"

namespace tmu::tb {
namespace {

TEST(BankAddressTest, RtlEqualsGeometryCellOnEveryLayout) {
  const BankAddressBlock block;
  std::mt19937_64 rng(20261122);
  std::vector<Txn> items;
  for (int lw = 0; lw <= formats::kMaxMipLog2; ++lw) {
    for (int lh = 0; lh <= formats::kMaxMipLog2; ++lh) {
      for (bool blocks : {false, true}) {
        for (int planes : {1, formats::kPlanes}) {
          const texram::Geometry g(lw, lh, planes, blocks);
          items.push_back(BankAddressBlock::config_item(g));
          for (int l = 0; l < g.levels(); ++l) {
            const uint32_t sw = g.stored_width(l), sh = g.stored_height(l);
            const auto at = [&](uint32_t x, uint32_t y, int plane) {
              items.push_back(BankAddressBlock::position_item(l, x, y, plane));
            };
            if (size_t{sw} * sh <= 256) {
              for (uint32_t y = 0; y < sh; ++y) {
                for (uint32_t x = 0; x < sw; ++x) {
                  for (int p = 0; p < planes; ++p) at(x, y, p);
                }
              }
            } else {
              for (const auto& [x, y] :
                   {std::pair{0u, 0u}, {sw - 1, 0u}, {0u, sh - 1}, {sw - 1, sh - 1}}) {
                at(x, y, planes - 1);
              }
              for (int i = 0; i < 256; ++i) {
                at(static_cast<uint32_t>(rng() % sw), static_cast<uint32_t>(rng() % sh),
                   static_cast<int>(rng() % static_cast<uint64_t>(planes)));
              }
            }
          }
        }
      }
    }
  }
  const RunResult golden = block.engine("golden")->run(items, {});
  ASSERT_TRUE(golden.error.empty()) << golden.error;
  const RunResult rtl = block.engine("rtl")->run(items, {});
  ASSERT_TRUE(rtl.error.empty()) << rtl.error;
  ASSERT_EQ(rtl.outputs.size(), golden.outputs.size());
  size_t wrong = 0;
  for (size_t i = 0; i < golden.outputs.size(); ++i) {
    if (rtl.outputs[i] == golden.outputs[i] || ++wrong > 5) continue;
    const Txn& in = items[golden.output_items[i]];
    ADD_FAILURE() << block.inputs().describe(in) << ": rtl "
                  << block.outputs().describe(rtl.outputs[i]) << ", golden "
                  << block.outputs().describe(golden.outputs[i]);
  }
  EXPECT_EQ(wrong, 0u) << "of " << golden.outputs.size();
  std::cout << golden.outputs.size() << " positions checked\n";
}

// The unit checks nothing: a position beyond the level's stored size is the stimulus's error.
TEST(BankAddressTest, PositionOutsideTheLayoutIsAnError) {
  const BankAddressBlock block;
  const texram::Geometry g(4, 2, 1, false);
  const std::vector<Txn> items = {BankAddressBlock::config_item(g),
                                  BankAddressBlock::position_item(0, 16, 0, 0)};
  const RunResult r = block.engine("golden")->run(items, {});
  EXPECT_NE(r.error.find("outside the texture"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace tmu::tb
