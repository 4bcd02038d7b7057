// Fast footprint assembly (footprint/fast_footprint.hpp) against the scalar golden
// (footprint::plan, footprint::sample), bit for bit, on random fragments over every probe
// maximum, both q rules, the setup widths the co-simulation runs (default, d8t4f5, d16t10f12)
// and random ones, every border mode pair, texel configuration and filter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "common/test_patterns.hpp"
#include "footprint/fast_footprint.hpp"
#include "footprint/footprint.hpp"

namespace tmu::footprint {
namespace {

using texram::Border;
using texram::Filter;
using texram::SamplerConfig;
using texram::TexelKind;
using texram::TexramTexture;

std::string describe(const Config& c, const SamplerConfig& s, const Request& r) {
  return "N max 2^" + std::to_string(c.log2_max_probes) + " " + std::string(name(c.q_rule)) +
         " widths " + std::to_string(c.widths.deriv_bits) + "," +
         std::to_string(c.widths.table_bits) + "," + std::to_string(c.widths.log_frac) + " " +
         std::string(texram::name(s.kind)) + " " + std::string(texram::name(s.filter)) + " " +
         std::string(texram::name(s.border_u)) + "/" + std::string(texram::name(s.border_v)) +
         " fragment u " + std::to_string(r.u) + " v " + std::to_string(r.v) + " r1 (" +
         std::to_string(r.r1u) + ", " + std::to_string(r.r1v) + ") r2 (" + std::to_string(r.r2u) +
         ", " + std::to_string(r.r2v) + ")";
}

// The bench's fragments (major axis 2^[-1, 7) texels, anisotropy 1..8, any orientation) and
// the setup's hard cases: anisotropy far beyond the maximum, zero and parallel vectors, huge
// derivatives, positions at the port's ends (wrap and saturation of the probes).
std::vector<Request> fragments(std::mt19937& rng, int side, int count) {
  std::uniform_real_distribution<double> log_major(-2.0, 8.0), log_ratio(0.0, 7.0),
      angle(0.0, 2 * std::numbers::pi);
  const auto port = [](double texels) { return static_cast<int32_t>(std::lround(texels * 256)); };
  std::vector<Request> out;
  for (int i = 0; i < count; ++i) {
    const double major = std::exp2(log_major(rng)), minor = major / std::exp2(log_ratio(rng)),
                 a = angle(rng);
    Request r;
    r.u = static_cast<int32_t>(rng() % (3u * side * 256)) - side * 256;
    r.v = static_cast<int32_t>(rng() % (3u * side * 256)) - side * 256;
    r.r1u = port(major * std::cos(a));
    r.r1v = port(major * std::sin(a));
    r.r2u = port(-minor * std::sin(a));
    r.r2v = port(minor * std::cos(a));
    r.shade = static_cast<uint32_t>(rng());
    switch (rng() % 12) {
      case 0:  // a line: r2 parallel to r1, or zero
        r.r2u = rng() % 2 ? 0 : 2 * r.r1u;
        r.r2v = rng() % 2 ? 0 : 2 * r.r1v;
        break;
      case 1:  // both zero: a point
        r.r1u = r.r1v = r.r2u = r.r2v = 0;
        break;
      case 2:  // at the port's ends, derivatives of any size
        r.u = (rng() % 2 ? 1 : -1) * static_cast<int32_t>((1u << 24) - rng() % 4096);
        r.v = static_cast<int32_t>(rng() % (1u << 25)) - (1 << 24);
        r.r1u = static_cast<int32_t>(rng() % (1u << 25)) - (1 << 24);
        r.r2v = static_cast<int32_t>(rng() % (1u << 25)) - (1 << 24);
        break;
      case 3:  // r1 and r2 swapped: r2 the longer
        std::swap(r.r1u, r.r2u);
        std::swap(r.r1v, r.r2v);
        break;
      default:
        break;
    }
    out.push_back(r);
  }
  return out;
}

void expect_equal(const TexramTexture& t, const SamplerConfig& s, const Config& c,
                  const std::vector<Request>& rs) {
  const FastFootprint fast(t, s, c);
  std::vector<uint32_t> batch(rs.size());
  fast.sample_batch(rs, batch);
  for (size_t i = 0; i < rs.size(); ++i) {
    const Plan golden_plan = plan(rs[i], c), fast_plan = fast.plan(rs[i]);
    ASSERT_EQ(fast_plan.log2_n, golden_plan.log2_n) << describe(c, s, rs[i]);
    ASSERT_EQ(fast_plan.r2_longer, golden_plan.r2_longer) << describe(c, s, rs[i]);
    ASSERT_EQ(fast_plan.lambda, golden_plan.lambda) << describe(c, s, rs[i]);
    const uint32_t golden = sample(t, s, c, rs[i]);
    ASSERT_EQ(fast.sample(rs[i]), golden) << describe(c, s, rs[i]);
    ASSERT_EQ(batch[i], golden) << "batch: " << describe(c, s, rs[i]);
  }
}

// The bench's configuration (true colour, trilinear, wrap, N max 8, default widths) and every
// other probe maximum, q rule and setup width setting, with every border mode pair.
TEST(FootprintFastTest, EqualsTheGoldenOnEveryProbeMaximumAndWidthSetting) {
  const TexramTexture t = texram::import_image(patterns::noise(64, 64, 9), TexelKind::kTrueColour);
  std::mt19937 rng(21);
  const Widths settings[] = {Widths{}, {8, 4, 5}, {16, 10, 12}, {6, 1, 1}, {24, 10, 12}};
  for (int log2_max = 0; log2_max <= 4; ++log2_max) {
    for (QRule rule : {QRule::kHeights, QRule::kSides}) {
      for (const Widths& w : settings) {
        for (Border bu : {Border::kWrap, Border::kClamp, Border::kBorder, Border::kMirror}) {
          for (Border bv : {Border::kWrap, Border::kClamp, Border::kBorder, Border::kMirror}) {
            SamplerConfig s;
            s.kind = TexelKind::kTrueColour;
            s.border_u = bu;
            s.border_v = bv;
            s.border_rgba = static_cast<uint32_t>(rng());
            Config c;
            c.log2_max_probes = log2_max;
            c.q_rule = rule;
            c.widths = w;
            expect_equal(t, s, c, fragments(rng, 64, 20));
            if (HasFatalFailure()) return;  // the first difference is enough
          }
        }
      }
    }
  }
}

// Every texel configuration, filter, combine and addressing, random setup widths.
TEST(FootprintFastTest, EqualsTheGoldenOnEveryTexelConfiguration) {
  std::mt19937 rng(22);
  for (TexelKind kind : {TexelKind::kLuminance, TexelKind::kIndex, TexelKind::kTrueColour,
                         TexelKind::kSingle, TexelKind::kCcc}) {
    const TexramTexture t = texram::import_image(patterns::noise(32, 16, 4), kind, 1);
    for (Filter f : {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear}) {
      for (int i = 0; i < 8; ++i) {
        SamplerConfig s;
        s.kind = kind;
        s.filter = f;
        s.single_channel = static_cast<int>(rng() % 4);
        s.border_u = static_cast<Border>(rng() % 4);
        s.border_v = static_cast<Border>(rng() % 4);
        s.border_rgba = static_cast<uint32_t>(rng());
        s.combine = static_cast<texram::Combine>(rng() % 3);
        s.constant_rgba = static_cast<uint32_t>(rng());
        s.addressing = i == 0 ? texram::Addressing::kSphere : texram::Addressing::kTexel;
        s.widths = {static_cast<int>(1 + rng() % 8), static_cast<int>(1 + rng() % 8),
                    static_cast<int>(1 + rng() % 8)};
        Config c;
        c.log2_max_probes = static_cast<int>(rng() % 5);
        c.q_rule = rng() % 2 ? QRule::kHeights : QRule::kSides;
        c.widths = {static_cast<int>(6 + rng() % 19), static_cast<int>(1 + rng() % 10),
                    static_cast<int>(1 + rng() % 12)};
        expect_equal(t, s, c, fragments(rng, 32, 100));
        if (HasFatalFailure()) return;
      }
    }
  }
}

}  // namespace
}  // namespace tmu::footprint
