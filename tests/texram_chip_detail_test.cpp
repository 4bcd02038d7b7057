// Detail maps on the TEXRAM chip (golden/texram/chip/texram_chip.hpp): a texture DRF with the
// detail flag, linked to its offsets DRF (the u- and v-offset maps, one after the other in the
// memory) and that to its detail DRF, samples exactly as texram::sample_detail does, with the
// same number of accesses, for lambda above and below 0, both combine rules, one- and
// four-plane maps and the border modes; the chain goes on after the detail DRF.
#include <gtest/gtest.h>

#include <random>

#include "tests/detail_test_support.hpp"
#include "texram/chip/texram_chip.hpp"
#include "texram/page_model.hpp"

namespace tmu::texram::chip {
namespace {

using detail_test::kOne;

struct ChipWithDetail {
  detail_test::Scene scene;
  SamplerConfig config;
  ChipMemory memory;
  DrfFile drfs{};
};

// DRF 1 the texture (detail, linked to 2), 2 the offsets (linked to 3), 3 the detail map,
// linked to 4: a reflectance map (the texture again) to show the chain goes on.
void program(ChipWithDetail& c, DetailCombine rule) {
  const TexramTexture& t = c.scene.texture;
  const DetailMap& m = c.scene.map;
  Drf texture;
  texture.sampler = c.config;
  texture.log2_w = t.geometry.log2_width();
  texture.log2_h = t.geometry.log2_height();
  texture.base = 0;
  texture.detail = true;
  texture.detail_combine = rule;
  texture.link = 2;
  Drf offsets;
  offsets.op = DrfOp::kOffsets;
  offsets.sampler = offset_sampler(c.config);
  offsets.log2_w = texture.log2_w;
  offsets.log2_h = texture.log2_h;
  offsets.base = page_up(t.geometry.bank_cells());
  offsets.link = 3;
  Drf detail;
  detail.op = DrfOp::kDetail;
  detail.sampler = detail_sampler(m, c.config);
  detail.log2_w = m.detail.geometry.log2_width();
  detail.log2_h = m.detail.geometry.log2_height();
  detail.base = page_up(offsets_v_base(offsets) + m.offset_v.geometry.bank_cells());
  detail.link = 4;
  Drf again = texture;  // a plain map after the detail DRF
  again.op = DrfOp::kReflectance;
  again.detail = false;
  again.link = 0;
  c.memory.place(t, texture.base);
  c.memory.place(m.offset_u, offsets.base);
  c.memory.place(m.offset_v, offsets_v_base(offsets));
  c.memory.place(m.detail, detail.base);
  c.drfs[0] = texture;
  c.drfs[1] = offsets;
  c.drfs[2] = detail;
  c.drfs[3] = again;
}

void check(ChipWithDetail& c, DetailCombine rule, uint32_t seed) {
  program(c, rule);
  TexramChip chip(c.memory, c.scene.texture.clut);
  for (int n = 1; n <= 4; ++n) {
    for (const DrfWrite& w : drf_writes(n, c.drfs[static_cast<size_t>(n - 1)])) chip.write(w);
  }
  std::mt19937 rng(seed);
  const auto side = static_cast<int32_t>(c.scene.texture.geometry.texel_width(0));
  const DetailConfig dc{rule};
  size_t below = 0;
  for (int i = 0; i < 3000; ++i) {
    Request r;
    r.u = static_cast<int32_t>(rng() % static_cast<uint32_t>(3 * side * kOne)) - side * kOne;
    r.v = static_cast<int32_t>(rng() % static_cast<uint32_t>(3 * side * kOne)) - side * kOne;
    r.lambda = static_cast<int32_t>(rng() % (9 * kOne)) - 6 * kOne;  // -6 .. 3 levels
    if (i % 10 == 0) r.lambda = -(i / 10 % 5) * kOne;                // exactly 0, -1 .. -4
    r.shade = static_cast<uint32_t>(rng());
    below += r.lambda < 0;
    std::vector<DetailAccess> accesses;
    const uint32_t want = sample_detail(c.scene.texture, c.config, &c.scene.map, dc, r, &accesses);
    const size_t before = chip.accesses().size();
    std::vector<ChipOutput> out;
    size_t next = 0;
    chip.pixel({PixelParameter{1, r}}, next, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].rgba, want) << "request " << i << ": u " << r.u << " v " << r.v << " lambda "
                                 << r.lambda;
    // Then the reflectance DRF after the detail DRF: a plain sample at the same coordinates.
    SamplePlan plain;
    sample(c.scene.texture, c.config, r, &plain);
    accesses.push_back({DetailMapId::kTexture, plain});
    EXPECT_EQ(chip.accesses().size() - before, static_cast<size_t>(bank_accesses(accesses)))
        << "request " << i << " lambda " << r.lambda;
  }
  EXPECT_GT(below, 1500u);
  EXPECT_FALSE(chip.stats().step_limit);
}

TEST(TexramChipDetailTest, LuminanceWithAGreyDetailMapEqualsSampleDetail) {
  std::mt19937 rng(3);
  for (const DetailCombine rule : {DetailCombine::kReplace, DetailCombine::kModulate}) {
    for (const Border b : {Border::kWrap, Border::kBorder, Border::kMirror}) {
      ChipWithDetail c{
          detail_test::make_scene(
              import_image(patterns::smooth_field(64, 64, 5), TexelKind::kLuminance),
              import_image(detail_test::grey_detail(128, 128, 9), TexelKind::kLuminance),
              detail_test::random_offsets(64, 64, 1, rng),
              detail_test::random_offsets(64, 64, 1, rng)),
          detail_test::config(TexelKind::kLuminance, Filter::kTrilinear, b),
          {},
          {}};
      SCOPED_TRACE(static_cast<int>(b));
      check(c, rule, 11);
    }
  }
}

TEST(TexramChipDetailTest, TrueColourWithATrueColourDetailMapEqualsSampleDetail) {
  std::mt19937 rng(4);
  for (const DetailCombine rule : {DetailCombine::kReplace, DetailCombine::kModulate}) {
    ChipWithDetail c{
        detail_test::make_scene(
            import_image(patterns::smooth_field(32, 32, 7), TexelKind::kTrueColour),
            import_image(detail_test::grey_detail(64, 64, 8), TexelKind::kTrueColour),
            detail_test::random_offsets(32, 32, 16, rng),
            detail_test::random_offsets(32, 32, 16, rng)),
        detail_test::config(TexelKind::kTrueColour, Filter::kTrilinear, Border::kClamp),
        {},
        {}};
    check(c, rule, 12);
  }
}

}  // namespace
}  // namespace tmu::texram::chip
