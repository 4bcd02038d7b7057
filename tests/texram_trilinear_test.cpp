// The golden trilinear unit: levels and lambda at and beyond the ends, border modes far
// outside, every configuration, the blend and combine rules, and its error against the ideal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "common/test_patterns.hpp"
#include "tests/error_stats.hpp"
#include "texram/trilinear.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::texram {
namespace {

constexpr int32_t kOne = 256;  // one texel / one level in raw SQ.8

TexramTexture texture(TexelKind kind, int w = 64, int h = 32, uint32_t seed = 3) {
  return import_image(patterns::smooth_field(w, h, seed), kind, 1);
}

SamplerConfig config(Filter f, Border b = Border::kWrap, TexelKind kind = TexelKind::kLuminance) {
  SamplerConfig c;
  c.kind = kind;
  c.filter = f;
  c.border_u = c.border_v = b;
  c.border_rgba = rgba(10, 200, 30, 40);
  c.single_channel = 1;
  return c;
}

// --- levels and lambda ---------------------------------------------------------------------

TEST(TexramTrilinearTest, NegativeLambdaMagnifiesFromLevelZero) {
  const TexramTexture t = texture(TexelKind::kTrueColour);
  const SamplerConfig tri = config(Filter::kTrilinear, Border::kWrap, TexelKind::kTrueColour);
  const SamplerConfig bil = config(Filter::kBilinear, Border::kWrap, TexelKind::kTrueColour);
  std::mt19937 rng(1);
  for (int i = 0; i < 2000; ++i) {
    const auto u = static_cast<int32_t>(rng() % (64 * kOne)),
               v = static_cast<int32_t>(rng() % (32 * kOne));
    const uint32_t level0 = sample(t, bil, {u, v, 0, 0});
    for (int32_t lambda : {0, -1, -kOne, -16 * kOne, -32 * kOne}) {
      SamplePlan plan;
      ASSERT_EQ(sample(t, tri, {u, v, lambda, 0}, &plan), level0) << "lambda raw " << lambda;
      EXPECT_EQ(plan.levels_read, 1);
      EXPECT_EQ(plan.level[0], 0);
    }
  }
}

TEST(TexramTrilinearTest, LambdaAtAndBeyondTheTopClamps) {
  const TexramTexture t = texture(TexelKind::kLuminance, 64, 32);  // levels 0..6
  const int top = t.geometry.levels() - 1;
  ASSERT_EQ(top, 6);
  for (Filter f : {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear}) {
    const SamplerConfig c = config(f);
    const uint32_t at_top = sample(t, c, {5 * kOne, 7 * kOne, top * kOne, 0});
    for (int32_t lambda : {top * kOne + 1, (top + 1) * kOne, 31 * kOne + 255}) {
      SamplePlan plan;
      EXPECT_EQ(sample(t, c, {5 * kOne, 7 * kOne, lambda, 0}, &plan), at_top) << name(f);
      EXPECT_EQ(plan.level[0], top);
      EXPECT_EQ(plan.levels_read, 1);
    }
    // The 1 x 1 top level is one texel: every coordinate gives it.
    EXPECT_EQ(sample(t, c, {-12345, 99999, top * kOne, 0}), at_top) << name(f);
  }
}

TEST(TexramTrilinearTest, TrilinearAtAWholeLevelEqualsBilinearThere) {
  const TexramTexture t = texture(TexelKind::kIndex);
  for (int l = 0; l < t.geometry.levels(); ++l) {
    for (int32_t u = -700; u < 70 * kOne; u += 613) {
      const Request r{u, u / 3, l * kOne, 0};
      EXPECT_EQ(sample(t, config(Filter::kTrilinear, Border::kMirror, TexelKind::kIndex), r),
                sample(t, config(Filter::kBilinear, Border::kMirror, TexelKind::kIndex), r));
    }
  }
}

TEST(TexramTrilinearTest, NearestAndBilinearUseTheRoundedLevel) {
  const TexramTexture t = texture(TexelKind::kLuminance);
  SamplePlan plan;
  sample(t, config(Filter::kBilinear), {0, 0, 2 * kOne + 127, 0}, &plan);
  EXPECT_EQ(plan.level[0], 2);
  sample(t, config(Filter::kBilinear), {0, 0, 2 * kOne + 128, 0}, &plan);
  EXPECT_EQ(plan.level[0], 3);  // round half up
  sample(t, config(Filter::kNearest), {0, 0, -kOne / 2, 0}, &plan);
  EXPECT_EQ(plan.level[0], 0);
  EXPECT_EQ(plan.taps_per_level, 1);
}

// --- border modes far outside --------------------------------------------------------------

TEST(TexramTrilinearTest, BorderModesFarOutsideTheTexture) {
  const TexramTexture t = texture(TexelKind::kTrueColour, 16, 8);
  const SamplerConfig wrap = config(Filter::kBilinear, Border::kWrap, TexelKind::kTrueColour);
  const SamplerConfig clamp = config(Filter::kBilinear, Border::kClamp, TexelKind::kTrueColour);
  const SamplerConfig mirror = config(Filter::kBilinear, Border::kMirror, TexelKind::kTrueColour);
  const SamplerConfig border = config(Filter::kBilinear, Border::kBorder, TexelKind::kTrueColour);
  const int32_t max_u = formats::kTexCoord.max_raw() - 32 * kOne;
  for (int32_t u = 3; u < 16 * kOne; u += 37) {
    const int32_t v = (u * 5) % (8 * kOne);
    const Request in{u, v, 0, 0};
    // wrap repeats with the period of the texture, as far as the port reaches
    for (int32_t k : {-1000, -1, 1, 7, 1000}) {
      const int32_t far = u + k * 16 * kOne;
      if (far > max_u || far < -max_u) continue;
      EXPECT_EQ(sample(t, wrap, {far, v, 0, 0}), sample(t, wrap, in));
      // mirror has twice the period: an odd number of texture widths reflects u to n - u
      const int32_t mirrored = k % 2 != 0 ? 16 * kOne - u : u;
      EXPECT_EQ(sample(t, mirror, {far, v, 0, 0}), sample(t, mirror, {mirrored, v, 0, 0}));
    }
    // clamp: beyond the right edge everything is the edge column
    EXPECT_EQ(sample(t, clamp, {40000 * kOne / 2, v, 0, 0}),
              sample(t, clamp, {16 * kOne + 100 * kOne, v, 0, 0}));
    // border: a whole texel outside, only the border colour
    EXPECT_EQ(sample(t, border, {-2 * kOne, v, 0, 0}), border.border_rgba);
    EXPECT_EQ(sample(t, border, {u, 9 * kOne, 0, 0}), border.border_rgba);
  }
  // the extremes of the port format
  for (int32_t u : {int32_t(formats::kTexCoord.min_raw()), int32_t(formats::kTexCoord.max_raw())}) {
    for (const SamplerConfig& c : {wrap, clamp, mirror, border}) {
      EXPECT_NO_THROW(sample(t, c, {u, u, 0, 0}));
      EXPECT_NO_THROW(sample(t, c, {u, -u, 10 * kOne, 0}));
    }
  }
}

TEST(TexramTrilinearTest, OneTexelTextureIsEverywhereItsTexel) {
  ImageRgb8 img(1, 1);
  img.pixels[0] = {200, 100, 50};
  for (TexelKind kind :
       {TexelKind::kLuminance, TexelKind::kTrueColour, TexelKind::kIndex, TexelKind::kCcc}) {
    const TexramTexture t = import_image(img, kind);
    const uint32_t texel = texel_rgba(t, config(Filter::kNearest, Border::kWrap, kind), 0, 0, 0);
    for (Border b : {Border::kWrap, Border::kClamp, Border::kMirror}) {
      for (Filter f : {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear}) {
        for (int32_t u : {-99999, -1, 0, 128, 255, 256, 77777}) {
          EXPECT_EQ(sample(t, config(f, b, kind), {u, u / 2, u % 2000, 0}), texel) << name(kind);
        }
      }
    }
  }
}

// --- configurations ------------------------------------------------------------------------

// The definitions golden and the ideal share (texel configurations, the RGBA8888 packing, the
// CCC block word) read alike: at every texel of every level the banks (golden, through the
// layout) and the source (the ideal's own decoding) give the same colour; exactly where the
// levels are given, within the pyramid's 0.5 where they are the box rule's.
TEST(TexramTrilinearTest, GoldenAndIdealReadTheSameTexelsAtEveryLevel) {
  const ImageRgb8 img = patterns::noise(32, 8, 5);
  for (TexelKind kind : {TexelKind::kLuminance, TexelKind::kIndex, TexelKind::kTrueColour,
                         TexelKind::kSingle, TexelKind::kCcc}) {
    for (int channel_index : {0, 3}) {
      const TexramTexture t = import_image(img, kind, channel_index);
      const IdealTexture ideal = ideal_texture(t.source);
      ASSERT_EQ(ideal.levels(), t.geometry.levels());
      SamplerConfig c = config(Filter::kNearest, Border::kWrap, kind);
      c.single_channel = channel_index;
      const bool given = kind == TexelKind::kIndex || kind == TexelKind::kCcc;
      for (int l = 0; l < t.geometry.levels(); ++l) {
        for (uint32_t y = 0; y < t.geometry.texel_height(l); ++y) {
          for (uint32_t x = 0; x < t.geometry.texel_width(l); ++x) {
            const uint32_t g = texel_rgba(t, c, l, x, y);
            const auto e = ideal_texel(ideal, c, l, x, y);
            for (int ch = 0; ch < 4; ++ch) {
              ASSERT_LE(std::abs(channel(g, ch) - e[static_cast<size_t>(ch)]),
                        given || l == 0 ? 0.0 : 0.5)
                  << name(kind) << " level " << l << " (" << x << ", " << y << ") channel " << ch;
            }
          }
        }
      }
    }
  }
}

TEST(TexramTrilinearTest, EachConfigurationReturnsItsTexelsAtTexelCentres) {
  const ImageRgb8 img = patterns::smooth_field(32, 16, 9);
  for (TexelKind kind : {TexelKind::kLuminance, TexelKind::kIndex, TexelKind::kTrueColour,
                         TexelKind::kSingle, TexelKind::kCcc}) {
    const TexramTexture t = import_image(img, kind, 1);
    for (uint32_t y = 0; y < 16; ++y) {
      for (uint32_t x = 0; x < 32; ++x) {
        const Request centre{static_cast<int32_t>(x) * kOne + kOne / 2,
                             static_cast<int32_t>(y) * kOne + kOne / 2, 0, 0};
        const SamplerConfig c = config(Filter::kBilinear, Border::kClamp, kind);
        const uint32_t got = sample(t, c, centre);
        ASSERT_EQ(got, texel_rgba(t, c, 0, x, y)) << name(kind) << " (" << x << ", " << y << ")";
        const Rgb8 p = img.at(static_cast<int>(x), static_cast<int>(y));
        switch (kind) {
          case TexelKind::kLuminance:
            ASSERT_EQ(got, rgba(luma(p), luma(p), luma(p), 255));
            break;
          case TexelKind::kTrueColour:
            ASSERT_EQ(got, rgba(p.r, p.g, p.b, 255));
            break;
          case TexelKind::kSingle:
            ASSERT_EQ(got, rgba(0, p.g, 0, 255));
            break;
          default:
            break;  // quantized: index and CCC are checked against their CLUT above
        }
      }
    }
  }
}

// --- blend and combine ---------------------------------------------------------------------

TEST(TexramTrilinearTest, ConstantTextureStaysConstantAtEveryWidth) {
  ImageRgb8 img(8, 8);
  for (Rgb8& p : img.pixels) p = {255, 0, 77};
  const TexramTexture t = import_image(img, TexelKind::kTrueColour);
  std::mt19937 rng(5);
  for (int s = 1; s <= 8; ++s) {
    for (int w = 1; w <= 8; ++w) {
      SamplerConfig c = config(Filter::kTrilinear, Border::kWrap, TexelKind::kTrueColour);
      c.widths = {s, w, 8 - (s + w) % 8};
      for (int i = 0; i < 200; ++i) {
        const Request r{static_cast<int32_t>(rng() % 100000) - 50000,
                        static_cast<int32_t>(rng() % 9999),
                        static_cast<int32_t>(rng() % 1200) - 100, 0};
        ASSERT_EQ(sample(t, c, r), rgba(255, 0, 77, 255)) << "S" << s << " W" << w;
      }
    }
  }
}

TEST(TexramTrilinearTest, Mul255IsRoundedExactlyForEveryPair) {
  for (uint32_t t = 0; t < 256; ++t) {
    for (uint32_t m = 0; m < 256; ++m) {
      // t m / 255 is never exactly half-way (2 t m is even, 255 (2k + 1) is odd).
      ASSERT_EQ(mul255(t, m), (2 * t * m + 255) / 510) << t << " * " << m;
    }
  }
}

TEST(TexramTrilinearTest, CombineSelectsOneConstantOrShade) {
  const TexramTexture t = texture(TexelKind::kTrueColour);
  SamplerConfig c = config(Filter::kBilinear, Border::kWrap, TexelKind::kTrueColour);
  const Request r{1000, 2000, 0, rgba(128, 255, 0, 64)};
  const uint32_t tex = sample(t, c, r);
  c.combine = Combine::kConstant;
  c.constant_rgba = rgba(255, 255, 255, 255);
  EXPECT_EQ(sample(t, c, r), tex);
  c.constant_rgba = 0;
  EXPECT_EQ(sample(t, c, r), 0u);
  c.combine = Combine::kShade;
  const uint32_t shaded = sample(t, c, r);
  for (int ch = 0; ch < 4; ++ch)
    EXPECT_EQ(channel(shaded, ch), mul255(channel(tex, ch), channel(r.shade, ch)));
}

// --- error against the ideal model ---------------------------------------------------------

using test::ErrorStats;

// Requests on the port grid (SQ16.8, SQ6.8), a texture wide on either side and lambda below 0
// and above the top, so the only differences are the unit's internal widths, its pyramid and
// its one rounding.
ErrorStats golden_vs_ideal(const TexramTexture& t, const SamplerConfig& c, uint32_t seed,
                           int count) {
  std::mt19937 rng(seed);
  ErrorStats e;
  const IdealTexture ideal_tex = ideal_texture(t.source);
  const int w = static_cast<int>(t.geometry.texel_width(0)),
            h = static_cast<int>(t.geometry.texel_height(0));
  for (int i = 0; i < count; ++i) {
    const Request r{static_cast<int32_t>(rng() % (3 * w * kOne)) - w * kOne,
                    static_cast<int32_t>(rng() % (3 * h * kOne)) - h * kOne,
                    static_cast<int32_t>(rng() % ((t.geometry.levels() + 2) * kOne)) - kOne,
                    static_cast<uint32_t>(rng())};
    const uint32_t g = sample(t, c, r);
    const auto ideal =
        ideal_sample(ideal_tex, c, r.u / 256.0, r.v / 256.0, r.lambda / 256.0, r.shade);
    for (int ch = 0; ch < 4; ++ch) e.add(std::abs(channel(g, ch) - ideal[static_cast<size_t>(ch)]));
  }
  return e;
}

// The textures of the bound: a smooth field, noise (the largest texel differences) and a
// black-and-white checker of 3-texel squares (box means that are neither 0 nor 255 next to
// ones that are: the pyramid's rounding and the steepest edges at once), 64 x 16 (the non-square
// levels too).
std::vector<std::pair<const char*, ImageRgb8>> bound_images() {
  return {{"smooth", patterns::smooth_field(64, 16, 3)},
          {"noise", patterns::noise(64, 16, 4)},
          {"checker", patterns::checker(64, 16, 3, {0, 0, 0}, {255, 255, 255})}};
}

// Golden against the independent ideal (texram/trilinear_ideal.hpp: the exact box pyramid of
// level 0, its own addressing, borders and decoding), per channel in 8-bit levels, at the
// default widths (S = W = L = 8). Every request is within 2, because the error has three parts:
// - the texels: level 0 is the source's own; a level above 0 of a luminance, single or
//   true-colour texture is golden's pyramid, each texel within 0.5 of the exact box mean
//   (carried sums, texram/mipmap.hpp); index and CCC levels are given, so exact: <= 0.5, and
//   the filter's convex weights keep it so;
// - the weights: the coordinate is rounded to 8 fraction bits at the level, so each weight is
//   within 2^-9 of the exact one, and a lerp between texels at most 255 apart moves by at most
//   255 / 512 per axis: <= 0.996 for both; lambda is on the port's 8-bit grid, the level weight
//   exact (L = W = 8), and the level blend convex: nothing more;
// - the one rounding of the result: <= 0.5.
// 0.5 + 0.996 + 0.5 < 2. Nearest reads one texel: its 0.5. The combine (shade, constant) scales
// by at most 1 and rounds once more: + 0.5. The three parts reach their ends together only on
// steep edges whose texels err the same way, so almost every request is within 1: the issue asks
// 99.9 %, measured here per texel kind and border mode over the three textures, every filter
// and both combines (with the combine's extra rounding counted against the same 1).
TEST(TexramTrilinearTest, GoldenIsWithinTwoOfTheIdealAndWithinOneAlmostAlways) {
  const double bound[3] = {0.5, 2.0, 2.0};
  for (TexelKind kind : {TexelKind::kLuminance, TexelKind::kIndex, TexelKind::kTrueColour,
                         TexelKind::kSingle, TexelKind::kCcc}) {
    std::vector<TexramTexture> textures;
    for (const auto& [label, image] : bound_images())
      textures.push_back(import_image(image, kind, 1));
    for (Border b : {Border::kWrap, Border::kClamp, Border::kBorder, Border::kMirror}) {
      ErrorStats all;
      for (const TexramTexture& t : textures) {
        for (Filter f : {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear}) {
          for (Combine m : {Combine::kOne, Combine::kShade}) {
            SamplerConfig c = config(f, b, kind);
            c.combine = m;
            const ErrorStats e = golden_vs_ideal(t, c, 11, 2000);
            EXPECT_LE(e.max(), bound[static_cast<int>(f)] + (m == Combine::kOne ? 0.0 : 0.5))
                << name(kind) << " " << name(f) << " " << name(b) << " " << name(m);
            // A correctly rounded result errs uniformly within +-0.5 (mean 0.25); a bias
            // (truncation) would push the mean toward 0.5, the combine's rounding adds 0.25.
            EXPECT_LE(e.mean(), m == Combine::kOne ? 0.3 : 0.5)
                << name(kind) << " " << name(f) << " " << name(b) << " " << name(m);
            all.add(e);
          }
        }
      }
      EXPECT_LE(all.share_above(1.0), 0.001) << name(kind) << " " << name(b);
      std::cout << name(kind) << " " << name(b) << ": 99.9th percentile " << all.percentile(0.999)
                << ", max " << all.max() << ", above 1: " << 100 * all.share_above(1.0)
                << " %, mean " << all.mean() << "\n";
    }
  }
}

// At level 0 on the port grid the weights are exact: the one rounding is the only error.
TEST(TexramTrilinearTest, AtLevelZeroTheOnlyErrorIsTheRounding) {
  const TexramTexture t = import_image(patterns::noise(32, 32, 8), TexelKind::kTrueColour);
  const IdealTexture ideal_tex = ideal_texture(t.source);
  std::mt19937 rng(12);
  for (Filter f : {Filter::kBilinear, Filter::kTrilinear}) {
    ErrorStats e;
    for (int i = 0; i < 20000; ++i) {
      const Request r{static_cast<int32_t>(rng() % (32 * kOne)),
                      static_cast<int32_t>(rng() % (32 * kOne)),
                      -static_cast<int32_t>(rng() % kOne), 0};
      const uint32_t g = sample(t, config(f, Border::kWrap, TexelKind::kTrueColour), r);
      const auto ideal = ideal_sample(ideal_tex, config(f, Border::kWrap, TexelKind::kTrueColour),
                                      r.u / 256.0, r.v / 256.0, r.lambda / 256.0);
      for (int ch = 0; ch < 4; ++ch)
        e.add(std::abs(channel(g, ch) - ideal[static_cast<size_t>(ch)]));
    }
    EXPECT_LE(e.max(), 0.5) << name(f);
    std::cout << name(f) << " at level 0: max " << e.max() << ", mean " << e.mean() << "\n";
  }
}

}  // namespace
}  // namespace tmu::texram
