// The golden footprint assembly (golden/footprint/footprint.hpp): the log2 unit, the hard
// cases of the setup (zero, parallel, equal and huge vectors, ratios beyond the maximum,
// magnification), probes across borders, the accumulator at its largest sums, symmetry, and
// the error against the ideal model with the bounds reasoned out next to them.
#include "footprint/footprint.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include "common/test_patterns.hpp"
#include "footprint/footprint_ideal.hpp"
#include "texram/trilinear.hpp"

namespace tmu::footprint {
namespace {

using texram::Border;
using texram::Filter;
using texram::SamplerConfig;
using texram::TexelKind;
using texram::TexramTexture;

constexpr int32_t kOne = 256;  // one texel in raw SQ16.8

int32_t raw(double texels) { return static_cast<int32_t>(std::lround(texels * kOne)); }

Request request(double u, double v, glm::dvec2 r1, glm::dvec2 r2) {
  return {raw(u), raw(v), raw(r1.x), raw(r1.y), raw(r2.x), raw(r2.y), 0};
}

Config config(int log2_max = 4, QRule rule = QRule::kHeights) {
  Config c;
  c.log2_max_probes = log2_max;
  c.q_rule = rule;
  return c;
}

SamplerConfig sampler(Filter f = Filter::kTrilinear, Border b = Border::kWrap) {
  SamplerConfig s;
  s.kind = TexelKind::kTrueColour;
  s.filter = f;
  s.border_u = s.border_v = b;
  s.border_rgba = texram::rgba(200, 0, 0, 255);
  return s;
}

TexramTexture solid(int w, int h, Rgb8 colour) {
  ImageRgb8 image(w, h);
  for (Rgb8& p : image.pixels) p = colour;
  return texram::import_image(image, TexelKind::kTrueColour);
}

TexramTexture smooth(int w = 128, int h = 64) {
  return texram::import_image(patterns::smooth_field(w, h, 5), TexelKind::kTrueColour);
}

double lambda_of(const Plan& p) { return p.lambda / double(kOne); }

// --- the log2 unit --------------------------------------------------------------------------

TEST(FootprintLog2Test, TableEntriesAreCorrectlyRoundedForEveryWidth) {
  for (int t = 1; t <= 10; ++t) {
    for (int f = 1; f <= 12; ++f) {
      const Widths w{12, t, f};
      for (uint32_t i = 0; i <= (1u << t); ++i) {
        const double exact = std::ldexp(std::log2(1 + i / std::ldexp(1, t)), f);
        ASSERT_EQ(log2_table_entry(i, w), static_cast<uint32_t>(std::lround(exact)))
            << "T " << t << " F " << f << " i " << i;
      }
    }
  }
}

// lg(x) / 2^F is within half a table interval, log2(1 + 2^-(T+1)), plus half a unit of the
// F-bit rounding, of log2 x; powers of two are exact; and it never decreases (lambda and k are
// monotonic in it).
TEST(FootprintLog2Test, ErrorIsWithinHalfAnIntervalAndMonotonic) {
  for (const Widths w : {Widths{12, 7, 8}, Widths{12, 4, 6}, Widths{12, 10, 12}}) {
    const double bound =
        std::log2(1 + std::ldexp(1, -(w.table_bits + 1))) + std::ldexp(0.5, -w.log_frac) + 1e-12;
    int64_t previous = -1;
    std::mt19937_64 rng(3);
    for (uint64_t x = 1; x < (uint64_t{1} << 48); x += 1 + (x >> 9) + rng() % (1 + (x >> 12))) {
      const Log2 l = log2_fixed(x, w);
      ASSERT_FALSE(l.zero);
      EXPECT_LE(std::abs(std::ldexp(double(l.value), -w.log_frac) - std::log2(double(x))), bound)
          << x;
      ASSERT_GE(l.value, previous) << x;
      previous = l.value;
    }
    EXPECT_TRUE(log2_fixed(0, w).zero);
    for (int e = 0; e < 48; ++e) {
      EXPECT_EQ(log2_fixed(uint64_t{1} << e, w).value, int64_t{e} << w.log_frac);
    }
  }
}

// --- hard cases of the setup -----------------------------------------------------------------

// A square footprint: one probe, at lambda = log2 |r| (to the log tables' error), and the
// result is exactly the trilinear unit's sample there.
TEST(FootprintTest, IsotropicFootprintIsOneTrilinearSample) {
  const TexramTexture t = smooth();
  const SamplerConfig s = sampler();
  for (double len : {1.5, 3.0, 10.0, 200.0}) {
    for (double angle : {0.0, 0.3, 1.0, 2.5}) {
      const glm::dvec2 r1 = len * glm::dvec2(std::cos(angle), std::sin(angle));
      const glm::dvec2 r2 = len * glm::dvec2(-std::sin(angle), std::cos(angle));
      const Request q = request(17.3, 9.6, r1, r2);
      const Plan p = plan(q, config());
      EXPECT_EQ(p.log2_n, 0) << len << " " << angle;
      EXPECT_NEAR(lambda_of(p), std::log2(len), 0.02) << len << " " << angle;
      EXPECT_EQ(sample(t, s, config(), q), texram::sample(t, s, {q.u, q.v, p.lambda, 0}));
    }
  }
}

// One vector zero, or both parallel: the footprint is a line, rho is infinite, so N is the
// maximum (or the quarter-texel spacing's bound), the probes march along the non-zero (longer)
// vector, and lambda is the spacing log2(|r| / N) so that the N probes cover the line.
TEST(FootprintTest, LineFootprintsTakeTheMaximumProbes) {
  const struct {
    glm::dvec2 r1, r2;
    bool r2_longer;
  } cases[] = {
      {{0, 0}, {24, 0}, true},    // r1 zero
      {{24, 0}, {0, 0}, false},   // r2 zero
      {{16, 8}, {8, 4}, false},   // parallel
      {{8, 4}, {-16, -8}, true},  // antiparallel, r2 longer
      {{-3, 5}, {3, -5}, false},  // equal and opposite: ties go to r1
  };
  for (const auto& c : cases) {
    for (int kmax = 0; kmax <= 4; ++kmax) {
      const Plan p = plan(request(5, 5, c.r1, c.r2), config(kmax));
      const double longer = std::max(glm::length(c.r1), glm::length(c.r2));
      const int k = std::min(kmax, static_cast<int>(std::floor(std::log2(longer))) + 2);
      EXPECT_EQ(p.log2_n, k);
      EXPECT_EQ(p.r2_longer, c.r2_longer);
      EXPECT_NEAR(lambda_of(p), std::log2(longer) - k, 0.02);
    }
  }
}

// Both vectors zero: a point. One probe at the finest lambda (level 0, magnified).
TEST(FootprintTest, PointFootprintIsOneProbeAtLevelZero) {
  const TexramTexture t = smooth();
  const Plan p = plan(request(7.25, 3.5, {0, 0}, {0, 0}), config());
  EXPECT_EQ(p.log2_n, 0);
  EXPECT_EQ(p.lambda, formats::kLod.min_raw());
  const SamplerConfig s = sampler();
  EXPECT_EQ(sample(t, s, config(), request(7.25, 3.5, {0, 0}, {0, 0})),
            texram::sample(t, s, {raw(7.25), raw(3.5), 0, 0}));
}

// Equal lengths: with the heights rule the parallelogram's shape decides (rho = 1 / sin of the
// angle between r1 and r2), with the sides rule it never sees the anisotropy: this is the
// effect of reading d1, d2 as the heights (docs/footprint.md).
TEST(FootprintTest, EqualLengthsAnisotropyDependsOnTheQRule) {
  const double len = 20;
  for (double degrees : {90.0, 60.0, 30.0, 10.0, 3.0}) {
    const double a = degrees * std::numbers::pi / 180;
    const glm::dvec2 r1{len, 0}, r2 = len * glm::dvec2(std::cos(a), std::sin(a));
    const Request q = request(1, 1, r1, r2);
    const int expected = std::min(4, static_cast<int>(std::floor(-std::log2(std::sin(a)) + 0.5)));
    EXPECT_EQ(plan(q, config(4, QRule::kHeights)).log2_n, expected) << degrees;
    EXPECT_EQ(plan(q, config(4, QRule::kSides)).log2_n, 0) << degrees;
  }
}

// Ratios beyond the maximum: N clamps and lambda rises to log2(|r_max| / N_max), above log2 q,
// so the N probes still cover the footprint's length (each probe wider than the footprint).
TEST(FootprintTest, RatiosBeyondTheMaximumRaiseLambda) {
  for (int kmax = 0; kmax <= 4; ++kmax) {
    const Plan p = plan(request(0, 0, {256, 0}, {0, 2}), config(kmax));  // ratio 128
    EXPECT_EQ(p.log2_n, kmax);
    EXPECT_NEAR(lambda_of(p), 8.0 - kmax, 0.02);
  }
  const Plan p = plan(request(0, 0, {256, 0}, {0, 16}), config(4));  // ratio 16: not clamped
  EXPECT_EQ(p.log2_n, 4);
  EXPECT_NEAR(lambda_of(p), 4.0, 0.02);  // log2 q
}

// N rounds to the nearest power of two geometrically: ratios below 2^(j + 1/2) give 2^j.
TEST(FootprintTest, ProbeCountRoundsAtTheGeometricMidpoint) {
  for (int j = 0; j < 4; ++j) {
    const double threshold = std::ldexp(std::numbers::sqrt2, j);
    EXPECT_EQ(plan(request(0, 0, {threshold * 0.99 * 8, 0}, {0, 8}), config()).log2_n, j);
    EXPECT_EQ(plan(request(0, 0, {threshold * 1.01 * 8, 0}, {0, 8}), config()).log2_n, j + 1);
  }
}

// Magnification: the longer vector under half a texel. One probe, lambda = log2 |r_max| < 0:
// exactly the level-0 sample at the centre.
TEST(FootprintTest, MagnificationIsOneProbe) {
  const TexramTexture t = smooth();
  const SamplerConfig s = sampler();
  for (const auto& [r1, r2] : {std::pair{glm::dvec2{0.49, 0}, glm::dvec2{0, 0.05}},
                               std::pair{glm::dvec2{0.3, 0.3}, glm::dvec2{0.01, -0.01}},
                               std::pair{glm::dvec2{0, 0.004}, glm::dvec2{0, 0}}}) {
    const Request q = request(30.2, 11.7, r1, r2);
    const Plan p = plan(q, config());
    EXPECT_EQ(p.log2_n, 0);
    EXPECT_LT(p.lambda, 0);
    const uint32_t level0 = texram::sample(t, s, {q.u, q.v, 0, 0});
    EXPECT_EQ(sample(t, s, config(), q), level0);
  }
}

// Probes stay at least a quarter texel apart: N <= 2^(floor(log2 |r_max|) + 2), so the cost
// grows with the footprint's length in texels, not with its ratio alone (a thin footprint of
// one texel does not take 16 probes). lambda then covers the spacing, log2 |r_max| - k.
TEST(FootprintTest, ProbesAreAtLeastAQuarterTexelApart) {
  const struct {
    double length;
    int k;
  } cases[] = {{0.49, 0}, {0.5, 1}, {0.99, 1}, {1.0, 2}, {1.99, 2}, {2.0, 3}, {4.0, 4}};
  for (const auto& c : cases) {
    const Plan p = plan(request(0, 0, {c.length, 0}, {0, 1.0 / 64}), config());
    EXPECT_EQ(p.log2_n, c.k) << c.length;
    EXPECT_NEAR(lambda_of(p), std::log2(c.length) - c.k, 0.02) << c.length;
    IdealConfig ic;
    ic.log2_max_probes = 4;
    EXPECT_EQ(ideal_plan({c.length, 0}, {0, 1.0 / 64}, ic).log2_n, c.k) << c.length;
  }
}

// Huge derivatives: lambda beyond the top level clamps in the trilinear unit, so every probe
// reads the top level. A solid texture gives its colour whatever the positions; probes far
// beyond the port's range wrap (wrap, mirror) or saturate (clamp, border) without overflow.
TEST(FootprintTest, HugeDerivativesStayInRange) {
  const TexramTexture t = solid(64, 64, {90, 180, 30});
  const uint32_t expected = texram::rgba(90, 180, 30, 255);
  const double big = 32767.0;
  for (Border b : {Border::kWrap, Border::kClamp, Border::kMirror}) {
    const SamplerConfig s = sampler(Filter::kTrilinear, b);
    for (const auto& [r1, r2] : {std::pair{glm::dvec2{big, 0}, glm::dvec2{0, big}},
                                 std::pair{glm::dvec2{big, big}, glm::dvec2{-big, 4}},
                                 std::pair{glm::dvec2{-big, -big}, glm::dvec2{0, 0}}}) {
      for (double c : {-32768.0, 0.0, 32767.0}) {
        const Request q = request(c, -c, r1, r2);
        const Plan p = plan(q, config());
        EXPECT_GE(lambda_of(p), 6.0);  // beyond the top level (6) of 64 x 64
        for (int i = 0; i < (1 << p.log2_n); ++i) {
          const texram::Request pr = probe(q, p, i, s);
          EXPECT_GE(pr.u, formats::kTexCoord.min_raw());
          EXPECT_LE(pr.u, formats::kTexCoord.max_raw());
        }
        EXPECT_EQ(sample(t, s, config(), q), expected);
      }
    }
  }
}

// Probe positions: p + n r / 2N for n = -(N-1) .. N-1, rounded half up to 1/256 texel; beyond
// the port's range they wrap modulo 2^16 texels (wrap, mirror) or saturate (clamp, border).
TEST(FootprintTest, ProbePositionsAreExactAndWrapOrSaturate) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 2000; ++trial) {
    Request q{static_cast<int32_t>(rng() % (1 << 24)) - (1 << 23),
              static_cast<int32_t>(rng() % (1 << 24)) - (1 << 23),
              static_cast<int32_t>(rng() % (1 << 24)) - (1 << 23),
              static_cast<int32_t>(rng() % (1 << 16)) - (1 << 15),
              static_cast<int32_t>(rng() % (1 << 12)) - (1 << 11),
              static_cast<int32_t>(rng() % (1 << 12)) - (1 << 11),
              0};
    const Plan p = plan(q, config());
    for (Border b : {Border::kWrap, Border::kClamp, Border::kBorder, Border::kMirror}) {
      const SamplerConfig s = sampler(Filter::kTrilinear, b);
      const int n_probes = 1 << p.log2_n;
      for (int i = 0; i < n_probes; ++i) {
        const double n = 2 * i - (n_probes - 1);
        const double du = p.r2_longer ? q.r2u : q.r1u;
        const double exact = std::floor(q.u + n * du / (2 * n_probes) + 0.5);
        const texram::Request pr = probe(q, p, i, s);
        if (b == Border::kWrap || b == Border::kMirror) {
          const double wrapped = std::fmod(exact - pr.u, 65536.0 * kOne);
          EXPECT_EQ(wrapped, 0.0) << "probe " << i;
        } else {
          EXPECT_EQ(pr.u, std::clamp(exact, -8388608.0, 8388607.0)) << "probe " << i;
        }
      }
    }
  }
}

// Probes across the border. r1 = 16 texels along u centred on u = 0: 16 probes at texel
// centres -7.5 .. 7.5, half outside. Border mode: exactly half border colour; clamp: all the
// edge; wrap and mirror: the texels they fold onto.
TEST(FootprintTest, ProbesAcrossTheBorderInEveryMode) {
  ImageRgb8 image(32, 32);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) image.at(x, y) = {static_cast<uint8_t>(x * 8), 100, 255};
  }
  const TexramTexture t = texram::import_image(image, TexelKind::kTrueColour);
  const Request q = request(0, 8.5, {16, 0}, {0, 1});
  ASSERT_EQ(plan(q, config()).log2_n, 4);
  auto red_of = [&](Border b) {
    return texram::channel(sample(t, sampler(Filter::kBilinear, b), config(), q), 0);
  };
  // Texel x for each probe: -8 .. -1 outside, 0 .. 7 inside; round half up of sum / 16.
  const auto avg = [](auto texel_value) {
    int sum = 0;
    for (int x = -8; x < 8; ++x) sum += texel_value(x);
    return static_cast<uint32_t>((sum + 8) >> 4);
  };
  EXPECT_EQ(red_of(Border::kBorder), avg([](int x) { return x < 0 ? 200 : x * 8; }));
  EXPECT_EQ(red_of(Border::kClamp), avg([](int x) { return x < 0 ? 0 : x * 8; }));
  EXPECT_EQ(red_of(Border::kWrap), avg([](int x) { return ((x + 32) % 32) * 8; }));
  EXPECT_EQ(red_of(Border::kMirror), avg([](int x) { return (x < 0 ? -x - 1 : x) * 8; }));
}

// The accumulator: 16 x 255 = 4080 needs 12 bits and must neither wrap nor saturate; the
// average rounds half up.
TEST(FootprintTest, AccumulatorAtItsLargestSums) {
  std::vector<uint32_t> all(16, 0xFFFFFFFFu);
  EXPECT_EQ(average(all, 4), 0xFFFFFFFFu);
  std::vector<uint32_t> half(16, 0xFEFEFEFEu);
  for (int i = 0; i < 8; ++i) half[static_cast<size_t>(i)] = 0xFFFFFFFFu;
  EXPECT_EQ(average(half, 4), 0xFFFFFFFFu);  // 254.5 rounds up
  std::vector<uint32_t> low(16, 0u);
  low[0] = 0x07080807u;  // 7/16 rounds down, 8/16 up
  EXPECT_EQ(average(low, 4), 0x00010100u);
  EXPECT_EQ(average(std::vector<uint32_t>{0x12345678u}, 0), 0x12345678u);

  const TexramTexture white = solid(16, 16, {255, 255, 255});
  const Request q = request(3, 3, {40, 3}, {-1, 2});
  ASSERT_EQ(plan(q, config()).log2_n, 4);
  EXPECT_EQ(sample(white, sampler(), config(), q), 0xFFFFFFFFu);
}

// Negating either vector, or swapping unequal ones, describes the same parallelogram: the
// same N and lambda, the same probes (mirrored order), the same colour.
TEST(FootprintTest, SymmetricDescriptionsGiveTheSameResult) {
  const TexramTexture t = smooth();
  const SamplerConfig s = sampler();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> d(-40, 40);
  for (int i = 0; i < 500; ++i) {
    const glm::dvec2 r1{d(rng), d(rng)}, r2{d(rng) / 8, d(rng) / 8};
    if (glm::length(r1) == glm::length(r2)) continue;
    const Request a = request(20, 10, r1, r2);
    const Plan pa = plan(a, config());
    for (const Request& b :
         {request(20, 10, -r1, r2), request(20, 10, r1, -r2), request(20, 10, r2, r1)}) {
      const Plan pb = plan(b, config());
      EXPECT_EQ(pb.log2_n, pa.log2_n);
      EXPECT_EQ(pb.lambda, pa.lambda);
      EXPECT_EQ(sample(t, s, config(), b), sample(t, s, config(), a));
    }
  }
}

// --- against the ideal model -----------------------------------------------------------------

// lambda: the default widths (D 12, T 7, F 8) put each lg within 0.0056 + 0.002 of log2; lambda
// = lg(a) - lg(smax)/2 (heights) combines 1.5 of those, then rounds to 1/256: 0.012 + 0.002.
// Truncating the components to 12 significant bits adds a relative error up to 2^-11 to each,
// which the cross product of nearly parallel vectors amplifies by the ratio (at most 2^6 here):
// 2^-5 relative, 0.045 in log2. Measured below and bounded at 0.05. N agrees except where rho
// is within that error of a rounding threshold.
TEST(FootprintAccuracyTest, SetupAgainstTheIdeal) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), ratio_log(0, 6),
      length_log(-3, 12);
  double worst = 0, sum = 0;
  int count = 0, k_differs = 0;
  for (int i = 0; i < 200000; ++i) {
    const double a = angle(rng), len = std::exp2(length_log(rng)),
                 ratio = std::exp2(ratio_log(rng)), skew = angle(rng) / 8 - 0.4;
    const glm::dvec2 r1 = len * glm::dvec2(std::cos(a), std::sin(a));
    const glm::dvec2 r2 = len / ratio * glm::dvec2(-std::sin(a + skew), std::cos(a + skew));
    const Request q = request(0, 0, r1, r2);
    // The ideal model on the same (port-rounded) vectors, so only the setup's widths differ.
    const glm::dvec2 q1{q.r1u / 256.0, q.r1v / 256.0}, q2{q.r2u / 256.0, q.r2v / 256.0};
    IdealConfig ic;
    ic.log2_max_probes = 4;
    const IdealPlan ip = ideal_plan(q1, q2, ic);
    const Plan p = plan(q, config());
    if (!std::isfinite(ip.lambda)) continue;
    if (p.log2_n != ip.log2_n) {
      ++k_differs;
      continue;
    }
    const double e = std::abs(lambda_of(p) - std::max(ip.lambda, -32.0));
    worst = std::max(worst, e);
    sum += e;
    ++count;
  }
  std::cout << "lambda error against ideal: max " << worst << ", mean " << sum / count
            << "; N differs on " << k_differs << " of 200000\n";
  EXPECT_LE(worst, 0.05);
  EXPECT_LE(k_differs, 200000 / 100);  // rho within ~0.03 of a threshold: about 1 %
}

// The colour: golden against the ideal footprint assembly on a smooth texture, where both
// pick the same N. Per probe the trilinear unit is within 1.5 levels (docs/texram.md); lambda
// off by up to 0.05 moves the level blend by 5 % of the difference between adjacent levels
// (small on a smooth field), the probe positions by 1/512 texel, and the average rounds once
// (0.5): bounded at 2.5 levels, mean error well under one.
TEST(FootprintAccuracyTest, ColourAgainstTheIdeal) {
  const TexramTexture t = smooth(256, 256);
  const texram::IdealTexture ideal_tex = texram::ideal_texture(t.source);
  const SamplerConfig s = sampler();
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), ratio_log(0, 5),
      length_log(-1, 7), pos(0, 256);
  double worst = 0, sum = 0;
  int count = 0;
  for (int i = 0; i < 20000; ++i) {
    const double a = angle(rng), len = std::exp2(length_log(rng)),
                 ratio = std::exp2(ratio_log(rng));
    const glm::dvec2 r1 = len * glm::dvec2(std::cos(a), std::sin(a));
    const glm::dvec2 r2 = len / ratio * glm::dvec2(-std::sin(a), std::cos(a));
    const Request q = request(pos(rng), pos(rng), r1, r2);
    const glm::dvec2 uv{q.u / 256.0, q.v / 256.0};
    const glm::dvec2 q1{q.r1u / 256.0, q.r1v / 256.0}, q2{q.r2u / 256.0, q.r2v / 256.0};
    IdealConfig ic;
    ic.log2_max_probes = 4;
    if (ideal_plan(q1, q2, ic).log2_n != plan(q, config()).log2_n) continue;
    const auto ideal = ideal_sample(ideal_tex, s, ic, uv, q1, q2, 0);
    const uint32_t golden = sample(t, s, config(), q);
    for (int c = 0; c < 3; ++c) {
      const double e = std::abs(texram::channel(golden, c) - ideal[static_cast<size_t>(c)]);
      worst = std::max(worst, e);
      sum += e;
      ++count;
    }
  }
  std::cout << "colour error against ideal: max " << worst << ", mean " << sum / count << "\n";
  EXPECT_LE(worst, 2.5);
  EXPECT_LE(sum / count, 0.5);
}

// The cheap direction against the exact one (eq. 12-18): equal for rectangles, apart for
// skewed parallelograms; both approach the supersampled footprint better than one probe.
TEST(FootprintIdealTest, EllipseAxisEqualsTheLongerSideForRectangles) {
  IdealConfig side, axis;
  side.log2_max_probes = axis.log2_max_probes = 4;
  axis.direction = Direction::kEllipseAxis;
  for (double a : {0.0, 0.4, 1.3, 2.9}) {
    const glm::dvec2 r1 = 12.0 * glm::dvec2(std::cos(a), std::sin(a));
    const glm::dvec2 r2 = 1.5 * glm::dvec2(-std::sin(a), std::cos(a));
    const IdealPlan ps = ideal_plan(r1, r2, side), pa = ideal_plan(r1, r2, axis);
    EXPECT_EQ(ps.log2_n, pa.log2_n);
    EXPECT_NEAR(ps.lambda, pa.lambda, 1e-9);
    EXPECT_NEAR(std::abs(glm::dot(glm::normalize(ps.step), glm::normalize(pa.step))), 1.0, 1e-9);
  }
  // A skewed parallelogram: r1 = (10, 0), r2 = (9, 1): the ellipse's axis is near the diagonal.
  const IdealPlan ps = ideal_plan({10, 0}, {9, 1}, side), pa = ideal_plan({10, 0}, {9, 1}, axis);
  EXPECT_GT(glm::length(pa.step), glm::length(ps.step));
  EXPECT_GT(pa.log2_n, ps.log2_n);
}

TEST(FootprintIdealTest, AssemblyApproachesTheSupersampledFootprint) {
  const TexramTexture t = texram::import_image(
      patterns::checker(256, 256, 4, {0, 0, 0}, {255, 255, 255}), TexelKind::kTrueColour);
  const texram::IdealTexture ideal_tex = texram::ideal_texture(t.source);
  const SamplerConfig s = sampler();
  IdealConfig one, many;
  one.log2_max_probes = 0;
  many.log2_max_probes = 4;
  double e_one = 0, e_many = 0;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> pos(0, 256), angle(0, 3);
  for (int i = 0; i < 300; ++i) {
    const double a = angle(rng);
    const glm::dvec2 r1 = 24.0 * glm::dvec2(std::cos(a), std::sin(a));
    const glm::dvec2 r2 = 1.5 * glm::dvec2(-std::sin(a), std::cos(a));
    const glm::dvec2 uv{pos(rng), pos(rng)};
    const auto ref = supersampled(ideal_tex, s, uv, r1, r2, 0);
    const auto a1 = ideal_sample(ideal_tex, s, one, uv, r1, r2, 0);
    const auto a16 = ideal_sample(ideal_tex, s, many, uv, r1, r2, 0);
    for (size_t c = 0; c < 3; ++c) {
      e_one += std::pow(a1[c] - ref[c], 2);
      e_many += std::pow(a16[c] - ref[c], 2);
    }
  }
  std::cout << "rms against the supersampled footprint: 1 probe " << std::sqrt(e_one / 900)
            << ", 16 probes " << std::sqrt(e_many / 900) << "\n";
  EXPECT_LT(e_many, e_one / 4);
}

}  // namespace
}  // namespace tmu::footprint
