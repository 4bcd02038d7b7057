// The fast trilinear unit (texram/fast_trilinear.hpp) against the scalar golden
// (texram::sample), bit for bit, on random requests over every texel configuration, filter,
// border mode pair, combine, addressing, width and lambda range (magnification and beyond the
// top level), on textures down to 1 x 1.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/test_patterns.hpp"
#include "texram/fast_trilinear.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram {
namespace {

constexpr int32_t kOne = 256;  // one texel / one level in raw SQ.8

std::string describe(const SamplerConfig& c, const Request& r) {
  return std::string(name(c.kind)) + " " + std::string(name(c.filter)) + " " +
         std::string(name(c.border_u)) + "/" + std::string(name(c.border_v)) + " " +
         std::string(name(c.combine)) + " " + std::string(name(c.addressing)) + " widths " +
         std::to_string(c.widths.sub_texel) + "," + std::to_string(c.widths.weight) + "," +
         std::to_string(c.widths.lod_frac) + " request u " + std::to_string(r.u) + " v " +
         std::to_string(r.v) + " lambda " + std::to_string(r.lambda);
}

// A width: 8 half the time (the default), else any of 1..8.
int width(std::mt19937& rng) { return rng() % 2 ? 8 : static_cast<int>(1 + rng() % 8); }

// Requests around the texture (a few periods each way), with some anywhere in the int32 range;
// lambda from below 0 (magnification) to beyond the top level, and some anywhere.
std::vector<Request> requests(std::mt19937& rng, int w, int h, int top, int count) {
  std::vector<Request> out;
  const auto around = [&](int side) {
    return static_cast<int32_t>(rng() % (6u * static_cast<uint32_t>(side) * kOne)) -
           2 * side * kOne;
  };
  for (int i = 0; i < count; ++i) {
    Request r;
    const bool wild = rng() % 16 == 0;
    r.u = wild ? static_cast<int32_t>(rng()) : around(w);
    r.v = wild ? static_cast<int32_t>(rng()) : around(h);
    r.lambda = rng() % 32 == 0 ? static_cast<int32_t>(rng())
                               : static_cast<int32_t>(rng() % ((top + 6) * kOne)) - 3 * kOne;
    r.shade = static_cast<uint32_t>(rng());
    out.push_back(r);
  }
  out.push_back({std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max(),
                 std::numeric_limits<int32_t>::min(), 0x12345678});
  out.push_back({std::numeric_limits<int32_t>::max(), std::numeric_limits<int32_t>::min(),
                 std::numeric_limits<int32_t>::max(), 0x87654321});
  return out;
}

TEST(TexramFastTest, EqualsTheGoldenOnEveryConfiguration) {
  std::mt19937 rng(21);
  int configurations = 0;
  for (TexelKind kind : {TexelKind::kLuminance, TexelKind::kIndex, TexelKind::kTrueColour,
                         TexelKind::kSingle, TexelKind::kCcc}) {
    // Square, wide, tall, one texel: the small levels are stored replicated.
    for (auto [w, h] : {std::pair{32, 32}, std::pair{64, 8}, std::pair{2, 16}, std::pair{1, 1}}) {
      const TexramTexture t = import_image(patterns::noise(w, h, 7), kind, 2);
      const int top = t.geometry.levels() - 1;
      for (Filter f : {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear}) {
        for (Border bu : {Border::kWrap, Border::kClamp, Border::kBorder, Border::kMirror}) {
          for (Border bv : {Border::kWrap, Border::kClamp, Border::kBorder, Border::kMirror}) {
            SamplerConfig c;
            c.kind = kind;
            c.single_channel = static_cast<int>(rng() % 4);
            c.filter = f;
            c.border_u = bu;
            c.border_v = bv;
            c.border_rgba = static_cast<uint32_t>(rng());
            c.combine = static_cast<Combine>(rng() % 3);
            c.constant_rgba = static_cast<uint32_t>(rng());
            c.addressing = rng() % 4 == 0 ? Addressing::kSphere : Addressing::kTexel;
            // The default widths (the sampler's constant-shift loop) or random ones, each in
            // half the textures and filters of every border mode pair.
            const bool defaults = (configurations / 16 + configurations % 16) % 2 == 0;
            c.widths = defaults ? Widths{} : Widths{width(rng), width(rng), width(rng)};
            const FastTrilinear fast(t, c);
            const std::vector<Request> rs = requests(rng, w, h, top, 150);
            std::vector<uint32_t> batch(rs.size());
            fast.sample_batch(rs, batch);
            for (size_t i = 0; i < rs.size(); ++i) {
              const uint32_t golden = sample(t, c, rs[i]);
              ASSERT_EQ(fast.sample(rs[i]), golden) << describe(c, rs[i]);
              ASSERT_EQ(batch[i], golden) << "batch: " << describe(c, rs[i]);
            }
            ++configurations;
          }
        }
      }
    }
  }
  EXPECT_EQ(configurations, 5 * 4 * 3 * 16);
}

// Every width triple, the default configuration otherwise: the blend's lanes at their limits.
TEST(TexramFastTest, EqualsTheGoldenAtEveryWidth) {
  const TexramTexture t = import_image(patterns::noise(16, 16, 3), TexelKind::kTrueColour);
  std::mt19937 rng(5);
  for (int s = 1; s <= 8; ++s) {
    for (int w = 1; w <= 8; ++w) {
      for (int l = 1; l <= 8; ++l) {
        SamplerConfig c;
        c.kind = TexelKind::kTrueColour;
        c.widths = {s, w, l};
        const FastTrilinear fast(t, c);
        for (const Request& r : requests(rng, 16, 16, 4, 40)) {
          ASSERT_EQ(fast.sample(r), sample(t, c, r)) << describe(c, r);
        }
      }
    }
  }
}

TEST(TexramFastTest, RejectsWhatTheGoldenRejects) {
  const TexramTexture t = import_image(patterns::noise(4, 4, 1), TexelKind::kLuminance);
  SamplerConfig c;
  c.widths.weight = 9;
  EXPECT_THROW(FastTrilinear(t, c), std::invalid_argument);
  EXPECT_THROW(sample(t, c, Request{}), std::invalid_argument);
  // A replica that differs from its original (no constructor writes one): the prepared
  // texture keeps one copy, so it refuses rather than answer differently.
  TexramTexture bad = t;
  const int top = bad.geometry.levels() - 1;  // 1 x 1, stored as 2 x 2
  const BankCell replica = bad.geometry.cell(top, 1, 1);
  bad.banks[replica.bank][replica.address] ^= 1;
  EXPECT_THROW(FastTrilinear(bad, SamplerConfig{}), std::invalid_argument);
}

}  // namespace
}  // namespace tmu::texram
