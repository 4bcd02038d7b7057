// What is the TEXRAM chip block's own (000 §14; docs/texram_chip.md "The chip block"; the
// conformance suite, tests/conformance_test.cpp, checks what every block shares): the cycles
// of a step and of a pixel on the one-sample-at-a-time rtl sequencer.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "blocks/texram_chip/texram_chip_block.hpp"

namespace tmu::tb {
namespace {

using texram::chip::Drf;
using texram::chip::DrfFile;
using texram::chip::DrfOp;
using texram::chip::PixelParameter;

// The rtl's cycles per pixel: per step on a one-plane map at page hits, and per pixel besides.
constexpr uint64_t kChipCyclesPerStep1 = 14;
constexpr uint64_t kChipCyclesPerPixel = 3;
// An environment sampled: the colour through tmu_specular_combine.
constexpr uint64_t kChipCyclesCombine = 2;

// A chain of `length` DRFs 1 -> 2 -> ... on map `m` (nearest, wrap, texture ops, the last
// `last`, no new coordinates), and `pixels` pixels led by DRF 1 at one texel (page hits after
// the first).
std::vector<Txn> chain_items(const ChipMapPlacement& m, int length, int pixels,
                             DrfOp last = DrfOp::kTexture) {
  DrfFile file{};
  for (int n = 1; n <= length; ++n) {
    Drf& d = file[static_cast<size_t>(n - 1)];
    d.base = m.base;
    d.log2_w = m.setup.log2_w;
    d.log2_h = m.setup.log2_h;
    d.sampler = m.setup.config;
    d.sampler.filter = texram::Filter::kNearest;
    d.sampler.border_u = d.sampler.border_v = texram::Border::kWrap;
    d.sampler.addressing = texram::Addressing::kTexel;
    d.op = n < length ? DrfOp::kTexture : last;
    d.link = n < length ? n + 1 : 0;
  }
  std::vector<Txn> items;
  const TexramChipBlock block({});
  for (size_t i = 0; i < 256; ++i) {
    items.push_back(chip_clut_item(static_cast<uint8_t>(i), block.scene().clut[i]));
  }
  for (const Txn& t : chip_program_items(file)) items.push_back(t);
  PixelParameter p;
  p.lead = 1;
  p.request = {128, 128, 0, 0x8080'8080u};  // texel (0, 0)'s centre, level 0
  for (int k = 0; k < pixels; ++k) items.push_back(chip_param_item(p));
  return items;
}

// Cycles between colours, back to back without stalls, all page hits: 3 + 14 per step for a
// one-plane map (per pixel Idle, the last Check, Finish; per step Check, Issue and the
// trilinear unit's 12 from acceptance to its output, taken in Wait), 3 more per step for four
// byte planes, 2 more when an environment makes the colour go through the combine. The hls
// model is sequential too (its timing is its own).
TEST(TexramChipTest, CyclesPerStep) {
  const TexramChipBlock block({});
  const ChipScene& s = block.scene();
  const ChipMapPlacement* one = nullptr;
  const ChipMapPlacement* four = &s.maps[0];  // true colour
  for (const ChipMapPlacement& m : s.maps) {
    if (m.setup.config.kind == texram::TexelKind::kLuminance ||
        m.setup.config.kind == texram::TexelKind::kIndex)
      one = one ? one : &m;
  }
  ASSERT_NE(one, nullptr);
  for (const auto& [map, per_step] :
       {std::pair{one, kChipCyclesPerStep1}, std::pair{four, kChipCyclesPerStep1 + 3}}) {
    for (int length : {1, 2, 7}) {
      for (const DrfOp last : {DrfOp::kTexture, DrfOp::kEnvironment}) {
        const RunResult r =
            block.engine("rtl")->run(chain_items(*map, length, 20, last), RunOptions{});
        ASSERT_TRUE(r.error.empty()) << r.error;
        ASSERT_EQ(r.output_cycles.size(), 20u);
        const uint64_t combine = last == DrfOp::kEnvironment ? kChipCyclesCombine : 0;
        for (size_t k = 2; k < r.output_cycles.size(); ++k) {
          EXPECT_EQ(r.output_cycles[k] - r.output_cycles[k - 1],
                    kChipCyclesPerPixel + static_cast<uint64_t>(length) * per_step + combine)
              << "length " << length << ", op " << name(last) << ", output " << k;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tmu::tb
