#include "blocks/footprint/fragments.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "formats/formats.hpp"

namespace tmu::tb::fragments {
namespace {

namespace fmts = tmu::formats;

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel in raw .8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr int32_t kDerivMin = static_cast<int32_t>(fmts::kTexDeriv.min_raw());
constexpr int32_t kDerivMax = static_cast<int32_t>(fmts::kTexDeriv.max_raw());
static_assert(fmts::kTexDeriv.frac_bits == kFrac);

// Random draws from the generator's raw output (no std distributions: the integer stimulus is
// the same on every standard library; the few draws through exp2, cos and sin are rounded to
// raw port values).
int64_t draw(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}
double draw_unit(std::mt19937_64& rng) {  // [0, 1)
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}
// A length in raw units, log-uniform between 2^lo and 2^hi texels.
double draw_length(std::mt19937_64& rng, double lo, double hi) {
  return std::exp2(lo + (hi - lo) * draw_unit(rng)) * kOne;
}

}  // namespace

int32_t clamp_coord(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kCoordMin, kCoordMax));
}
int32_t clamp_deriv(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kDerivMin, kDerivMax));
}

footprint::Request fragment(int64_t u, int64_t v, int64_t r1u, int64_t r1v, int64_t r2u,
                            int64_t r2v, uint32_t shade) {
  return {clamp_coord(u),   clamp_coord(v), clamp_deriv(r1u), clamp_deriv(r1v), clamp_deriv(r2u),
          clamp_deriv(r2v), shade};
}

// The setup's configuration drawn from the generator (at most 1, 2, 4, 8 or 16 probes, the
// larger counts more often; either q rule), what the options set overriding its draw.
footprint::Config draw_setup(std::mt19937_64& rng, const BlockOptions& o) {
  constexpr int kMaxDraws[8] = {0, 1, 2, 3, 3, 4, 4, 4};
  footprint::Config c;
  c.log2_max_probes = kMaxDraws[rng() % 8];
  c.q_rule = rng() % 2 == 0 ? footprint::QRule::kHeights : footprint::QRule::kSides;
  c.log2_max_probes = o.fp_log2_max_probes.value_or(c.log2_max_probes);
  c.q_rule = o.fp_q_rule.value_or(c.q_rule);
  c.widths = o.fp_widths;
  const footprint::Widths& w = c.widths;
  if (w.deriv_bits < 6 || w.deriv_bits > 24 || w.table_bits < 1 || w.table_bits > 10 ||
      w.log_frac < 1 || w.log_frac > 12) {
    throw std::invalid_argument(
        "footprint: widths D,T,F must be deriv 6..24, table 1..10, log fraction 1..12");
  }
  if (c.log2_max_probes < 0 || c.log2_max_probes > fmts::kMaxProbeLog2) {
    throw std::invalid_argument("footprint: at most 1, 2, 4, 8 or 16 probes");
  }
  return c;
}

footprint::Config first_setup(const BlockOptions& options) {
  std::mt19937_64 rng(options.seed ^ 0xF007'9817'0000'0001ull);
  return draw_setup(rng, options);
}

std::vector<footprint::Request> directed(int64_t w, int64_t h) {
  std::vector<footprint::Request> out;
  uint32_t shade = 0x80FF'40C0u;
  auto frag = [&](int64_t u, int64_t v, int64_t r1u, int64_t r1v, int64_t r2u, int64_t r2v) {
    out.push_back(fragment(u, v, r1u, r1v, r2u, r2v, shade));
    shade = shade * 0x9E37'79B1u + 0x7F4A'7C15u;  // a different I_d each time
  };
  // An interior centre, off the texel grid.
  const int64_t cu = w / 2 + 77, cv = h / 3 + 41;

  // r1 zero: a line along r2 (area 0: rho is infinite): k = kmax, marching along r2
  // (s2 > s1), capped by the length (probes a quarter texel apart at least: |r2| ~ 3 texels
  // allows 8 probes, 5 texels 16), lambda = log2 |r2| - k. Heights and sides agree (smin = 0).
  frag(cu, cv, 0, 0, 3 * kOne, kOne / 2);
  frag(cu, cv, 0, 0, -kOne / 3, 5 * kOne);
  // r2 zero: the same along r1 (caps 8 and 16).
  frag(cu, cv, 3 * kOne, -kOne / 2, 0, 0);
  frag(cu, cv, -7 * kOne, 0, 0, 0);
  // Both zero: a point: k = 0, the smallest lambda (the finest level), one probe at the centre
  // (also on a texel edge and at the port's corner).
  frag(cu, cv, 0, 0, 0, 0);
  frag(kOne, kOne, 0, 0, 0, 0);
  frag(kCoordMin, kCoordMax, 0, 0, 0, 0);

  // r1 parallel to r2 (r2 = 2 r1): area 0: kmax probes along r2, the longer (|r2| ~ 4.5
  // texels: 16 at most).
  frag(cu, cv, 2 * kOne, kOne, 4 * kOne, 2 * kOne);
  // Antiparallel and equally long (r2 = -r1): area 0, s1 = s2: along r1 (r2 only when
  // strictly longer), kmax probes (|r1| ~ 2.2 texels: 8 at most).
  frag(cu, cv, 2 * kOne, kOne, -2 * kOne, -kOne);
  // Not parallel, but the cross product (-1 LSB^2) vanishes after the block-floating shift
  // (sh = 12 at D = 12): a line to the setup, kmax probes, lambda ~ log2 |r| - kmax.
  frag(cu, cv, 0x40'0000, 0x40'0001, 0x40'0001, 0x40'0002);

  // Isotropic (|r1| = |r2|, orthogonal): rho = 0: one probe, lambda = log2 |r| (2 texels:
  // ~1.0; rotated by 45 degrees: the same).
  frag(cu, cv, 2 * kOne, 0, 0, 2 * kOne);
  frag(cu, cv, 362, 362, -362, 362);
  // Equal lengths, 60 degrees apart: sides rho = 0 (k = 0); heights q = |r| sin 60, rho =
  // 2 log2(1 / sin 60) ~ 0.42: k = 0.
  frag(cu, cv, 4 * kOne, 0, 2 * kOne, 887);
  // Equal lengths, 10 degrees apart: sides k = 0; heights q = |r| sin 10, rho ~ 2.5: the
  // rounding threshold between 4 and 8 probes.
  frag(cu, cv, 4 * kOne, 0, 1008, 178);

  // The ratio |r1| / |r2| at the rounding thresholds 2^(j + 1/2) (orthogonal: heights and
  // sides agree), and a few LSB either side: k = j below, j + 1 above (clamped to kmax), up to
  // the table's error (the threshold is where it shows). Along u and v, r1 or r2 longer.
  for (int j = 0; j < fmts::kMaxProbeLog2; ++j) {
    const int64_t major = 16 * kOne;
    const auto minor = static_cast<int64_t>(std::lround(major / std::exp2(j + 0.5)));
    for (int64_t d = -2; d <= 2; ++d) {
      frag(cu, cv, major, 0, 0, minor + d);
      frag(cu, cv, minor + d, 0, 0, -major);  // r2 longer, along v
    }
  }
  // Exact powers of two: ratio 1, 2, 4, 8, 16 at a 2-texel minor side: k = 0 .. 4 (clamped).
  for (int j = 0; j <= fmts::kMaxProbeLog2; ++j) frag(cu, cv, (2 * kOne) << j, 0, 0, 2 * kOne);

  // Ratios far beyond the maximum N (64, 1000, 2^15 with a 1-LSB minor side): k = kmax
  // (clamped), lambda = max(log2 q, log2 |r_max| - kmax): fewer probes grow to cover the length.
  frag(cu, cv, 64 * kOne, 0, 0, kOne);
  frag(cu, cv, 0, 1000 * kOne, kOne, 0);
  frag(cu, cv, 128 * kOne, 128 * kOne, 1, -1);
  frag(cu, cv, kDerivMax, 0, 0, 1);

  // Magnification (|r_max| <= 1 texel): probes at least a quarter texel apart leave one
  // under half a texel, two under a texel, whatever the ratio; lambda < 0.
  frag(cu, cv, kOne / 2, 0, 0, kOne / 4);
  frag(cu, cv, kOne / 2, kOne / 3, 0, kOne / 64);
  frag(cu, cv, 1, 0, 0, 1);  // one LSB each
  frag(cu, cv, 1, 1, -1, 1);
  // The cap k <= floor(log2 |r_max|) + 2 at its steps, |r_max| = 1/4, 1/2, 1, 2, 4, 8 texels
  // and one LSB below (ratio 16: k would be 4 without it): one probe under 1/2 texel, then up
  // to 2, 4, 8, 16 probes from 1/2, 1, 2, 4 texels (clamped by kmax). Exact on the square's
  // leading one, also after a block-floating shift (at D = 8 a 1-texel component is shifted,
  // sh = 1).
  for (int64_t len = kOne / 4; len <= 8 * kOne; len *= 2) {
    for (int64_t d = -1; d <= 0; ++d) {
      frag(cu, cv, len + d, 0, 0, len / 16);
      frag(cu, cv, 0, len / 16, 0, -(len + d));  // r2 the longer
    }
  }

  // Huge derivatives (components at +-2^15 texels, beyond every level): lambda ~ 15 (the
  // trilinear unit clamps it to the top level), probes up to 15/32 of 2^15 texels from the
  // centre: beyond the port's range, they wrap (wrap, mirror) or saturate (clamp, border).
  frag(cu, cv, kDerivMax, 0, 0, kDerivMax);
  frag(cu, cv, kDerivMin, kDerivMin, kDerivMax, kDerivMin);
  frag(cu, cv, kDerivMin, kDerivMax, kDerivMax, kDerivMin);  // nearly antiparallel
  frag(cu, cv, kDerivMin, 0, 0, kOne);
  frag(kCoordMax, kCoordMin, kDerivMax, kDerivMax, kDerivMin, kDerivMax);
  // Every component at the largest magnitude 2^23 - 1 (all ones, 2^D - 1 after the shift,
  // where a power of two leaves 2^(D-1)): the squared lengths and the area, 2 (2^D - 1)^2,
  // reach the top bit of the logarithms' 2D + 1-bit operands (docs/coverage.md).
  frag(cu, cv, kDerivMax, kDerivMax, -kDerivMax, kDerivMax);
  // The largest ratio at D = 16 (no shift): (a, a - 1) and (a - 1, a - 2), a = 2^16 - 1,
  // nearly parallel, cross product -1 LSB^2: heights rho = log2(s_max / area) ~ 33.
  frag(cu, cv, 0xFFFF, 0xFFFE, 0xFFFE, 0xFFFD);

  // Probes crossing the texture's edges: centres a quarter texel inside u = 0, u = size, v = 0,
  // v = size and at the corners, 8-texel footprints across the edge: probes on both sides
  // (the border modes differ there).
  for (const auto& [u, v] :
       std::initializer_list<std::pair<int64_t, int64_t>>{{kOne / 4, h / 2},
                                                          {w - kOne / 4, h / 2},
                                                          {w / 2, kOne / 4},
                                                          {w / 2, h - kOne / 4},
                                                          {0, 0},
                                                          {w, h}}) {
    frag(u, v, 8 * kOne, 0, 0, kOne / 2);
    frag(u, v, kOne / 2, 0, 0, 8 * kOne);
    frag(u, v, 6 * kOne, 6 * kOne, -kOne / 2, kOne / 2);
  }
  // Near the port's range (+-2^15 texels): probes beyond it wrap modulo 2^16 texels (wrap,
  // mirror) or saturate (clamp, border).
  for (int64_t c : {int64_t{kCoordMax} - kOne, int64_t{kCoordMin} + kOne, int64_t{kCoordMax},
                    int64_t{kCoordMin}}) {
    frag(c, h / 2, 16 * kOne, 0, 0, kOne);
    frag(w / 2, c, kOne, 0, 0, -16 * kOne);
    frag(c, c, 8 * kOne, 8 * kOne, -kOne, kOne);
  }
  frag(kCoordMax, kCoordMax, kDerivMax, kDerivMax, 1, -1);  // far beyond, both axes

  return out;
}

footprint::Request random(std::mt19937_64& rng, int64_t w, int64_t h) {
  // A vector of length `len` (raw) at angle `a`.
  auto polar = [](double len, double a) {
    return std::pair<int64_t, int64_t>{std::llround(len * std::cos(a)),
                                       std::llround(len * std::sin(a))};
  };
  // The centre: mostly over the texture and around it, sometimes far, now and then anywhere
  // in the port's range.
  int64_t u, v;
  const uint64_t where = rng() % 100;
  if (where < 85) {
    u = draw(rng, -w / 4, w + w / 4);
    v = draw(rng, -h / 4, h + h / 4);
  } else if (where < 95) {
    u = draw(rng, -2 * w, 3 * w);
    v = draw(rng, -2 * h, 3 * h);
  } else {
    u = draw(rng, kCoordMin, kCoordMax);
    v = draw(rng, kCoordMin, kCoordMax);
  }
  const double angle = 2.0 * std::numbers::pi * draw_unit(rng);
  std::pair<int64_t, int64_t> r1, r2;
  const uint64_t kind = rng() % 100;
  if (kind < 25) {  // isotropic: equal and orthogonal, 1/4 to 64 texels
    const double len = draw_length(rng, -2, 6);
    r1 = polar(len, angle);
    r2 = polar(len, angle + std::numbers::pi / 2);
  } else if (kind < 70) {
    // Anisotropic: ratio 1 .. 64, the major side 1/2 .. 256 texels, the minor one mostly
    // orthogonal, sometimes skewed; r1 or r2 the longer.
    const double major = draw_length(rng, -1, 8);
    const double ratio = std::exp2(6.0 * draw_unit(rng));
    const double skew = rng() % 4 == 0 ? (draw_unit(rng) - 0.5) * std::numbers::pi / 2 : 0.0;
    r1 = polar(major, angle);
    r2 = polar(major / ratio, angle + std::numbers::pi / 2 + skew);
    if (rng() % 2 == 0) std::swap(r1, r2);
  } else if (kind < 82) {  // magnified: both shorter than a texel
    r1 = polar(draw_length(rng, -7, 0), angle);
    r2 = polar(draw_length(rng, -7, 0), angle + 2.0 * std::numbers::pi * draw_unit(rng));
  } else if (kind < 94) {  // degenerate
    const double len = draw_length(rng, -3, 9);
    switch (rng() % 5) {
      case 0:  // one vector zero
        r1 = polar(len, angle);
        r2 = {0, 0};
        if (rng() % 2 == 0) std::swap(r1, r2);
        break;
      case 1:  // both zero
        r1 = r2 = {0, 0};
        break;
      case 2: {  // parallel or antiparallel: r2 = t r1, |t| <= 2
        r1 = polar(len, angle);
        const int64_t t = draw(rng, -8, 8);
        r2 = {r1.first * t / 4, r1.second * t / 4};
        break;
      }
      case 3:  // a few LSB
        r1 = {draw(rng, -3, 3), draw(rng, -3, 3)};
        r2 = {draw(rng, -3, 3), draw(rng, -3, 3)};
        break;
      default:  // equal lengths, random angle between them
        r1 = polar(len, angle);
        r2 = polar(len, angle + 2.0 * std::numbers::pi * draw_unit(rng));
        break;
    }
  } else {  // components anywhere in the port's range, of random magnitudes
    auto component = [&rng] {
      const int bits = static_cast<int>(draw(rng, 0, 23));
      return draw(rng, -(int64_t{1} << bits), (int64_t{1} << bits) - 1);
    };
    r1 = {component(), component()};
    r2 = {component(), component()};
  }
  return fragment(u, v, r1.first, r1.second, r2.first, r2.second, static_cast<uint32_t>(rng()));
}

namespace {

constexpr const char* kClamped = "k clamped (ratio beyond the maximum N)";
constexpr const char* kLine = "line footprint (area 0, vectors not 0)";
constexpr const char* kOneZero = "one vector zero";
constexpr const char* kPoint = "point (both vectors zero)";
constexpr const char* kMagnified = "magnification (|r_max| < 1 texel)";
constexpr const char* kCapped = "k capped by the length (probes >= 1/4 texel apart)";
constexpr const char* kR2Longer = "r2 longer (marching along r2)";
constexpr const char* kEqual = "equal lengths (|r1| = |r2|, not 0)";
constexpr const char* kHuge = "huge derivative (a component >= 2^14 texels)";
constexpr const char* kLambdaNeg = "lambda < 0 (probes magnified)";

std::string q_case(footprint::QRule q) { return fmt::format("q rule {}", footprint::name(q)); }
std::string max_case(int log2_max) { return fmt::format("at most {} probes", 1 << log2_max); }
std::string k_case(int k) { return fmt::format("k = {} ({} probes)", k, 1 << k); }

}  // namespace

std::vector<std::string> shape_cases(const std::vector<footprint::QRule>& q_rules,
                                     const std::vector<int>& log2_max_probes) {
  std::vector<std::string> cases;
  for (const footprint::QRule q : q_rules) cases.push_back(q_case(q));
  for (const int m : log2_max_probes) cases.push_back(max_case(m));
  const int largest = *std::max_element(log2_max_probes.begin(), log2_max_probes.end());
  for (int k = 0; k <= largest; ++k) cases.push_back(k_case(k));
  cases.insert(cases.end(), {kClamped, kLine, kOneZero, kPoint, kMagnified, kR2Longer, kEqual,
                             kHuge, kLambdaNeg});
  if (largest > 0) cases.push_back(kCapped);
  return cases;
}

void cover_shape(const footprint::Request& req, const footprint::Config& c,
                 const footprint::Plan& p, Coverage& cov) {
  ++cov[q_case(c.q_rule)];
  ++cov[max_case(c.log2_max_probes)];
  ++cov[k_case(p.log2_n)];
  // The footprint's shape, in doubles (a classification, not the setup's arithmetic).
  const int64_t r1u = req.r1u, r1v = req.r1v, r2u = req.r2u, r2v = req.r2v;
  const bool zero1 = r1u == 0 && r1v == 0, zero2 = r2u == 0 && r2v == 0;
  const int64_t s1 = r1u * r1u + r1v * r1v, s2 = r2u * r2u + r2v * r2v;
  const int64_t cross = r1u * r2v - r1v * r2u;
  const double l1 = std::sqrt(static_cast<double>(s1)) / kOne;
  const double l2 = std::sqrt(static_cast<double>(s2)) / kOne;
  const double lmax = std::max(l1, l2);
  const double area = std::abs(static_cast<double>(cross)) / (double{kOne} * kOne);
  if (zero1 && zero2) {
    ++cov[kPoint];
  } else if (zero1 || zero2) {
    ++cov[kOneZero];
  } else if (cross == 0) {
    ++cov[kLine];
  }
  if (!(zero1 && zero2) && lmax < 1.0) ++cov[kMagnified];
  if (p.r2_longer) ++cov[kR2Longer];
  if (s1 == s2 && s1 != 0) ++cov[kEqual];
  if (std::max({std::abs(r1u), std::abs(r1v), std::abs(r2u), std::abs(r2v)}) >=
      (int64_t{1} << 14) * kOne) {
    ++cov[kHuge];
  }
  const double q = c.q_rule == footprint::QRule::kHeights ? area / lmax : std::min(l1, l2);
  if (q > 0.0 && lmax >= 1.0 && std::log2(lmax / q) > c.log2_max_probes + 0.5) ++cov[kClamped];
  // The ratio asks for more probes than the length allows (floor(log2 |r_max|) + 2: probes a
  // quarter texel apart at least).
  if (lmax > 0.0) {
    const double k_ratio =
        q > 0.0 ? std::min<double>(c.log2_max_probes, std::floor(std::log2(lmax / q) + 0.5))
                : c.log2_max_probes;
    if (std::max(0.0, std::floor(std::log2(lmax)) + 2.0) < k_ratio) ++cov[kCapped];
  }
  if (p.lambda < 0) ++cov[kLambdaNeg];
}

std::string setup_repro_options(const BlockOptions& o) {
  std::string out;
  auto add = [&out](const std::string& p) { out += (out.empty() ? "" : " ") + p; };
  if (o.fp_log2_max_probes) add(fmt::format("--max-probes {}", 1 << *o.fp_log2_max_probes));
  if (o.fp_q_rule) add(fmt::format("--q-rule {}", footprint::name(*o.fp_q_rule)));
  if (!(o.fp_widths == footprint::Widths{})) {
    add(fmt::format("--fp-widths {},{},{}", o.fp_widths.deriv_bits, o.fp_widths.table_bits,
                    o.fp_widths.log_frac));
  }
  return out;
}

std::string setup_variant(const footprint::Widths& w) {
  if (w == footprint::Widths{}) return "";
  return fmt::format("d{}t{}f{}", w.deriv_bits, w.table_bits, w.log_frac);
}

}  // namespace tmu::tb::fragments
