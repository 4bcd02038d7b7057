#include "footprint/footprint.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "formats/formats.hpp"

namespace tmu::footprint {
namespace {

constexpr int kPortFrac = formats::kTexCoord.frac_bits;  // 8: squares and areas carry 16

int64_t magnitude(int32_t c) { return c < 0 ? -int64_t{c} : int64_t{c}; }

// sign(c) * (|c| >> sh): truncation toward zero keeps the setup symmetric under negation.
int64_t shift_toward_zero(int32_t c, int sh) {
  const int64_t m = magnitude(c) >> sh;
  return c < 0 ? -m : m;
}

void check(const Widths& w) {
  if (w.deriv_bits < 6 || w.deriv_bits > 24 || w.table_bits < 1 || w.table_bits > 10 ||
      w.log_frac < 1 || w.log_frac > 12) {
    throw std::invalid_argument("footprint widths: deriv 6..24, table 1..10, log fraction 1..12");
  }
}

// A coordinate beyond the port: wrap modulo 2^16 texels, or saturate.
int32_t to_port(int64_t raw, texram::Border border) {
  constexpr int kW = formats::kTexCoord.width();
  constexpr int64_t kMin = -(int64_t{1} << (kW - 1)), kMax = (int64_t{1} << (kW - 1)) - 1;
  if (border == texram::Border::kWrap || border == texram::Border::kMirror) {
    const uint64_t bits = static_cast<uint64_t>(raw) & ((uint64_t{1} << kW) - 1);
    return static_cast<int32_t>(static_cast<int64_t>(bits << (64 - kW)) >> (64 - kW));
  }
  return static_cast<int32_t>(std::clamp(raw, kMin, kMax));
}

}  // namespace

uint32_t log2_table_entry(uint32_t index, const Widths& widths) {
  // The binary-logarithm digit recurrence on y = 1 + index / 2^T in Q1.30: square, and a
  // digit 1 halves y back into [1, 2). F + 1 digits, then rounded half up to F. Integer
  // arithmetic, truncating at 30 bits, so that the RTL's elaboration computes the same table.
  constexpr int kP = 30;
  const int t = widths.table_bits;
  uint64_t y = ((uint64_t{1} << t) + uint64_t{index}) << (kP - t);
  uint32_t digits = 0;
  for (int b = 0; b <= widths.log_frac; ++b) {
    y = (y * y) >> kP;
    const bool one = y >= (uint64_t{2} << kP);
    if (one) y >>= 1;
    digits = (digits << 1) | (one ? 1u : 0u);
  }
  return (digits + 1) >> 1;
}

Log2 log2_fixed(uint64_t x, const Widths& widths) {
  if (x == 0) return {};
  const int e = static_cast<int>(std::bit_width(x)) - 1;
  const int t = widths.table_bits;
  const uint64_t below = x - (uint64_t{1} << e);  // the bits under the leading one
  // The mantissa rounded half up to T bits (index 2^T is the next power of two).
  const uint64_t index = e > t ? ((below >> (e - t - 1)) + 1) >> 1 : below << (t - e);
  return {false,
          (int64_t{e} << widths.log_frac) + log2_table_entry(static_cast<uint32_t>(index), widths)};
}

Extents extents(const Request& r, const Widths& w) {
  const int64_t largest =
      std::max({magnitude(r.r1u), magnitude(r.r1v), magnitude(r.r2u), magnitude(r.r2v)});
  const int sh =
      std::max(0, static_cast<int>(std::bit_width(static_cast<uint64_t>(largest))) - w.deriv_bits);
  const int64_t a1u = shift_toward_zero(r.r1u, sh), a1v = shift_toward_zero(r.r1v, sh);
  const int64_t a2u = shift_toward_zero(r.r2u, sh), a2v = shift_toward_zero(r.r2v, sh);
  const int64_t cross = a1u * a2v - a1v * a2u;
  return {static_cast<uint64_t>(a1u * a1u + a1v * a1v),
          static_cast<uint64_t>(a2u * a2u + a2v * a2v),
          static_cast<uint64_t>(cross < 0 ? -cross : cross), sh};
}

Plan plan(const Request& r, const Config& config) {
  const Widths& w = config.widths;
  check(w);
  if (config.log2_max_probes < 0 || config.log2_max_probes > formats::kMaxProbeLog2) {
    throw std::invalid_argument("footprint: log2_max_probes must be 0..4");  // the RTL asserts it
  }
  const auto [s1, s2, area, sh] = extents(r, w);

  Plan p;
  p.r2_longer = s2 > s1;
  constexpr auto kLambdaMin = static_cast<int32_t>(formats::kLod.min_raw());
  constexpr auto kLambdaMax = static_cast<int32_t>(formats::kLod.max_raw());
  const Log2 lmax = log2_fixed(std::max(s1, s2), w);
  if (lmax.zero) {  // both vectors zero: a point, the finest level
    p.lambda = kLambdaMin;
    return p;
  }
  const int g = w.log_frac + 1;
  const int64_t offset = (int64_t{2 * sh} - 2 * kPortFrac) << w.log_frac;  // in G bits
  const int64_t log2_rmax = lmax.value + offset;

  bool unbounded = false;  // rho is infinite: the footprint is a line
  int64_t log2_q = 0, rho = 0;
  if (config.q_rule == QRule::kHeights) {
    const Log2 la = log2_fixed(area, w);
    unbounded = la.zero;
    log2_q = 2 * la.value - lmax.value + offset;
    rho = 2 * (lmax.value - la.value);
  } else {
    const Log2 lmin = log2_fixed(std::min(s1, s2), w);
    unbounded = lmin.zero;
    log2_q = lmin.value + offset;
    rho = lmax.value - lmin.value;
  }
  const int64_t kmax = config.log2_max_probes;
  int64_t k = unbounded ? kmax : std::min(kmax, (rho + (int64_t{1} << (g - 1))) >> g);
  // Probes at least a quarter texel apart: k <= floor(log2 |r_max|) + 2, exactly, from the
  // leading one of smax (floor(log2 sqrt x) = floor(floor(log2 x) / 2)).
  const int64_t e = static_cast<int64_t>(std::bit_width(std::max(s1, s2))) - 1;
  const int64_t floor_log2_rmax = (e + 2 * sh - 2 * kPortFrac) >> 1;  // arithmetic: floor
  k = std::min(k, std::max<int64_t>(0, floor_log2_rmax + 2));
  p.log2_n = static_cast<int>(k);

  const int64_t spread = log2_rmax - (k << g);
  const int64_t lambda_g = unbounded ? spread : std::max(log2_q, spread);
  const int64_t lambda =
      g >= kPortFrac
          ? (lambda_g + (g > kPortFrac ? int64_t{1} << (g - kPortFrac - 1) : 0)) >> (g - kPortFrac)
          : lambda_g << (kPortFrac - g);
  p.lambda = static_cast<int32_t>(std::clamp<int64_t>(lambda, kLambdaMin, kLambdaMax));
  return p;
}

texram::Request probe(const Request& r, const Plan& p, int i,
                      const texram::SamplerConfig& sampler) {
  const int k = p.log2_n;
  const int64_t n = 2 * int64_t{i} - ((int64_t{1} << k) - 1);  // -(N-1), -(N-3), ..., N-1
  const int64_t du = p.r2_longer ? r.r2u : r.r1u;
  const int64_t dv = p.r2_longer ? r.r2v : r.r1v;
  const auto at = [&](int64_t c, int64_t d) {
    return ((c << (k + 1)) + n * d + (int64_t{1} << k)) >> (k + 1);
  };
  texram::Request q;
  q.u = to_port(at(r.u, du), sampler.border_u);
  q.v = to_port(at(r.v, dv), sampler.border_v);
  q.lambda = p.lambda;
  q.shade = r.shade;
  return q;
}

uint32_t average(std::span<const uint32_t> colours, int log2_n) {
  uint32_t out = 0;
  for (int c = 0; c < 4; ++c) {
    uint32_t sum = 0;
    for (uint32_t rgba : colours) sum += texram::channel(rgba, c);
    const uint32_t half = log2_n > 0 ? 1u << (log2_n - 1) : 0;
    out |= ((sum + half) >> log2_n) << (24 - 8 * c);
  }
  return out;
}

uint32_t sample(const texram::TexramTexture& texture, const texram::SamplerConfig& sampler,
                const Config& config, const Request& request,
                std::vector<texram::SamplePlan>* probe_plans) {
  const Plan p = plan(request, config);
  std::array<uint32_t, 1 << formats::kMaxProbeLog2> colours{};
  const int n = 1 << p.log2_n;
  for (int i = 0; i < n; ++i) {
    texram::SamplePlan sp;
    colours[static_cast<size_t>(i)] =
        texram::sample(texture, sampler, probe(request, p, i, sampler), &sp);
    if (probe_plans) probe_plans->push_back(sp);
  }
  return average(std::span(colours.data(), static_cast<size_t>(n)), p.log2_n);
}

std::string_view name(QRule rule) { return rule == QRule::kHeights ? "heights" : "sides"; }

std::optional<QRule> parse_q_rule(std::string_view text) {
  if (text == "heights") return QRule::kHeights;
  if (text == "sides") return QRule::kSides;
  return std::nullopt;
}

}  // namespace tmu::footprint
