// What is the TEXRAM chip block's own (000 §14; docs/texram_chip.md "The chip block"; the
// conformance suite, tests/conformance_test.cpp, checks what every block shares): the cycles
// of a step and of a pixel on the one-step-at-a-time rtl sequencer, plain, with footprint
// assembly and with a detail map, and of the pixels it streams (one-step texture chains).
#include "texram/chip/texram_chip.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <tuple>
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
// A pixel whose chain is one plain texture step streams behind the one before: an access a
// clock, one for a one-plane map, four for four byte planes.
constexpr uint64_t kChipCyclesStreamed1 = 1;
constexpr uint64_t kChipCyclesStreamed4 = 4;
// An environment sampled: the colour through tmu_specular_combine.
constexpr uint64_t kChipCyclesCombine = 2;
// A detail sample: Check, Issue, 13 a read (its issue and the unit's 12), the colour's cycle.
constexpr uint64_t kChipCyclesDetailStep = 3;
constexpr uint64_t kChipCyclesPerRead = 13;

// The CLUT and `file`.
std::vector<Txn> program_items(const DrfFile& file) {
  std::vector<Txn> items;
  const TexramChipBlock block({});
  for (size_t i = 0; i < 256; ++i) {
    items.push_back(chip_clut_item(static_cast<uint8_t>(i), block.scene().clut[i]));
  }
  for (const Txn& t : chip_program_items(file)) items.push_back(t);
  return items;
}

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
  std::vector<Txn> items = program_items(file);
  PixelParameter p;
  p.lead = 1;
  p.request = {128, 128, 0, 0x8080'8080u};  // texel (0, 0)'s centre, level 0
  for (int k = 0; k < pixels; ++k) items.push_back(chip_param_item(p));
  return items;
}

// Cycles between colours, back to back without stalls, all page hits: 3 + 14 per step for a
// one-plane map (per pixel Idle, the last Check, Finish; per step Check, Issue and the
// trilinear unit's 12 from acceptance to its output, taken in Wait), 3 more per step for four
// byte planes, 2 more when an environment makes the colour go through the combine; a chain of
// one texture step streams (1 or 4). The hls model is sequential (its timing is its own).
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
  for (const auto& [map, per_step, streamed] :
       {std::tuple{one, kChipCyclesPerStep1, kChipCyclesStreamed1},
        std::tuple{four, kChipCyclesPerStep1 + 3, kChipCyclesStreamed4}}) {
    for (int length : {1, 2, 7}) {
      for (const DrfOp last : {DrfOp::kTexture, DrfOp::kEnvironment}) {
        const RunResult r =
            block.engine("rtl")->run(chain_items(*map, length, 20, last), RunOptions{});
        ASSERT_TRUE(r.error.empty()) << r.error;
        ASSERT_EQ(r.output_cycles.size(), 20u);
        const uint64_t combine = last == DrfOp::kEnvironment ? kChipCyclesCombine : 0;
        const uint64_t per_pixel =
            length == 1 && last == DrfOp::kTexture
                ? streamed
                : kChipCyclesPerPixel + static_cast<uint64_t>(length) * per_step + combine;
        for (size_t k = 2; k < r.output_cycles.size(); ++k) {
          EXPECT_EQ(r.output_cycles[k] - r.output_cycles[k - 1], per_pixel)
              << "length " << length << ", op " << name(last) << ", output " << k;
        }
      }
    }
  }
}

// A one-step emit chain (a bump map's pass) streams too: each pixel gives its sample (last 0)
// and then its colour (last 1) the next clock, so a pixel takes 2 cycles on a one-plane map (the
// unit's one sample a clock is not the limit: the output is) and 4 on a four-plane map.
TEST(TexramChipTest, StreamedEmitPixels) {
  const TexramChipBlock block({});
  const ChipScene& s = block.scene();
  const ChipMapPlacement* one = nullptr;
  for (const ChipMapPlacement& m : s.maps) {
    if (!four_planes(m.setup.config.kind)) one = one ? one : &m;
  }
  ASSERT_NE(one, nullptr);
  for (const auto& [map, per_pixel] :
       {std::pair{one, uint64_t{2}}, std::pair{&s.maps[0], uint64_t{4}}}) {
    ASSERT_TRUE(four_planes(s.maps[0].setup.config.kind));
    const RunResult r =
        block.engine("rtl")->run(chain_items(*map, 1, 20, DrfOp::kEmit), RunOptions{});
    ASSERT_TRUE(r.error.empty()) << r.error;
    ASSERT_EQ(r.outputs.size(), 40u);
    for (size_t k = 0; k < r.outputs.size(); ++k) {
      EXPECT_EQ(r.outputs[k].f[desc::texram_chip::out_last], k % 2) << "output " << k;
      if (k % 2 == 1) {
        EXPECT_EQ(r.outputs[k].f[desc::texram_chip::out_rgba], 0u) << "an emit chain's C_d";
        EXPECT_EQ(r.output_cycles[k] - r.output_cycles[k - 1], 1u) << "output " << k;
      }
      if (k >= 4 && k % 2 == 1) {
        EXPECT_EQ(r.output_cycles[k] - r.output_cycles[k - 2], per_pixel) << "output " << k;
      }
    }
  }
}

// Pixels led by DRF 1 of `file`, all at `p`, back to back: the rtl's cycles between colours are
// `per_pixel` plus one per slow access (a page fault) of the pixel, which golden's page model
// counts.
void expect_cycles(const TexramChipBlock& block, const DrfFile& file, const PixelParameter& p,
                   uint64_t per_pixel, const std::string& what) {
  constexpr size_t kPixels = 8;
  std::vector<Txn> items = program_items(file);
  for (size_t k = 0; k < kPixels; ++k) items.push_back(chip_param_item(p));
  const RunResult r = block.engine("rtl")->run(items, RunOptions{});
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_EQ(r.output_cycles.size(), kPixels) << what;
  texram::chip::TexramChip chip(*block.scene().memory, block.scene().clut);
  for (int n = 1; n <= texram::chip::kDrfs; ++n) {
    for (const auto& w : texram::chip::drf_writes(n, file[static_cast<size_t>(n - 1)]))
      chip.write(w);
  }
  for (size_t k = 0; k < kPixels; ++k) {
    const uint64_t before = chip.stats().pages.slow_accesses;
    std::vector<texram::chip::ChipOutput> out;
    size_t next = 0;
    chip.pixel({p}, next, out);
    const uint64_t slow = chip.stats().pages.slow_accesses - before;
    if (k == 0) continue;
    EXPECT_EQ(r.output_cycles[k] - r.output_cycles[k - 1], per_pixel + slow)
        << what << ", pixel " << k << " (" << slow << " slow accesses)";
  }
}

// A one-step chain with footprint assembly streams too: N cycles a pixel of N probes (one probe a
// clock through the trilinear unit, the next pixel's behind them); a detail sample takes 3 + 13
// a read (3 or 4 reads), one step at a time.
TEST(TexramChipTest, CyclesOfFootprintAndDetailSteps) {
  const TexramChipBlock block({});
  const ChipScene& s = block.scene();
  size_t plain = 0;
  while (four_planes(s.maps[plain].setup.config.kind)) ++plain;
  DrfFile file{};
  Drf& d = file[0];
  d.base = s.maps[plain].base;
  d.log2_w = s.maps[plain].setup.log2_w;
  d.log2_h = s.maps[plain].setup.log2_h;
  d.sampler = s.maps[plain].setup.config;
  d.sampler.filter = texram::Filter::kTrilinear;
  d.sampler.border_u = d.sampler.border_v = texram::Border::kWrap;
  d.footprint = true;
  d.log2_max_probes = 4;
  // r1 = (N, 0), r2 = (0, 1) texels: N probes a texel apart at lambda 0 (docs/footprint.md).
  for (const int32_t n : {1, 2, 4, 8, 16}) {
    PixelParameter p;
    p.lead = 1;
    p.request = {128, 128, 0, 0x8080'8080u};
    p.r1u = n * 256;
    p.r2v = 256;
    expect_cycles(block, file, p, static_cast<uint64_t>(n),
                  "footprint, " + std::to_string(n) + " probes");
  }
  // Texture 1 with a detail map: offsets 2, detail 3; replace at lambda -2 reads the offsets
  // twice and the detail map, modulate or -1 < lambda < 0 the texture too.
  // Offsets 1 are the index map's (one plane); a four-plane read takes 3 cycles more.
  std::mt19937_64 rng(5);
  ChipDetailDrfs c = chip_detail_drfs(rng, s, 1, 0);
  c.t.sampler.addressing = texram::Addressing::kTexel;
  c.t.footprint = false;
  c.t.link = 2;
  c.o.link = 3;
  c.d.link = 0;
  file = {c.t, c.o, c.d};
  for (const auto& [rule, lambda, reads] : {std::tuple{texram::DetailCombine::kReplace, -512, 3},
                                            std::tuple{texram::DetailCombine::kModulate, -512, 4},
                                            std::tuple{texram::DetailCombine::kReplace, -128, 4}}) {
    file[0].detail_combine = rule;
    PixelParameter p;
    p.lead = 1;
    p.request = {(1 << file[0].log2_w) * 128, 128, lambda, 0x8080'8080u};
    const uint64_t planes = four_planes(file[2].sampler.kind) ? 3 : 0;  // the detail map's
    expect_cycles(
        block, file, p,
        kChipCyclesPerPixel + kChipCyclesDetailStep +
            kChipCyclesPerRead * static_cast<uint64_t>(reads) + planes,
        "detail, " + std::to_string(reads) + " reads at lambda " + std::to_string(lambda));
  }
}

}  // namespace
}  // namespace tmu::tb
