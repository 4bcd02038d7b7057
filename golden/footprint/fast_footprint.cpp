#include "footprint/fast_footprint.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <stdexcept>
#include <string>

#include "formats/formats.hpp"
#include "texram/rgba_lanes.hpp"

namespace tmu::footprint {
namespace {

constexpr int kFastFpPortFrac = formats::kTexCoord.frac_bits;  // 8

// footprint.cpp's to_port: wrap modulo 2^16 texels, or saturate.
int32_t fast_to_port(int64_t raw, texram::Border border) {
  constexpr int kW = formats::kTexCoord.width();
  constexpr int64_t kMin = -(int64_t{1} << (kW - 1)), kMax = (int64_t{1} << (kW - 1)) - 1;
  if (border == texram::Border::kWrap || border == texram::Border::kMirror) {
    return static_cast<int32_t>(static_cast<int64_t>(static_cast<uint64_t>(raw) << (64 - kW)) >>
                                (64 - kW));
  }
  return static_cast<int32_t>(std::clamp(raw, kMin, kMax));
}

}  // namespace

FastFootprint::FastFootprint(const texram::TexramTexture& texture,
                             const texram::SamplerConfig& sampler, const Config& config)
    : unit_(texture, sampler), config_(config) {
  footprint::plan(Request{}, config);  // the golden's checks of the widths and maximum, once
  const int t = config.widths.table_bits;
  for (uint32_t i = 0; i <= (uint32_t{1} << t); ++i) {
    log_table_.push_back(log2_table_entry(i, config.widths));
  }
}

int64_t FastFootprint::lg(uint64_t x) const {
  const int e = static_cast<int>(std::bit_width(x)) - 1;
  const int t = config_.widths.table_bits;
  const uint64_t below = x - (uint64_t{1} << e);
  const uint64_t index = e > t ? ((below >> (e - t - 1)) + 1) >> 1 : below << (t - e);
  return (int64_t{e} << config_.widths.log_frac) + log_table_[index];
}

// footprint::plan with the table looked up; the comments there say why each step is so.
Plan FastFootprint::plan(const Request& r) const {
  const Widths& w = config_.widths;
  const auto [s1, s2, area, sh] = extents(r, w);

  Plan p;
  p.r2_longer = s2 > s1;
  constexpr auto kLambdaMin = static_cast<int32_t>(formats::kLod.min_raw());
  constexpr auto kLambdaMax = static_cast<int32_t>(formats::kLod.max_raw());
  const uint64_t smax = std::max(s1, s2);
  if (smax == 0) {
    p.lambda = kLambdaMin;
    return p;
  }
  const int64_t lmax = lg(smax);
  const int g = w.log_frac + 1;
  const int64_t offset = (int64_t{2 * sh} - 2 * kFastFpPortFrac) << w.log_frac;
  const int64_t log2_rmax = lmax + offset;

  bool unbounded = false;
  int64_t log2_q = 0, rho = 0;
  if (config_.q_rule == QRule::kHeights) {
    unbounded = area == 0;
    const int64_t la = unbounded ? 0 : lg(area);
    log2_q = 2 * la - lmax + offset;
    rho = 2 * (lmax - la);
  } else {
    const uint64_t smin = std::min(s1, s2);
    unbounded = smin == 0;
    const int64_t lmin = unbounded ? 0 : lg(smin);
    log2_q = lmin + offset;
    rho = lmax - lmin;
  }
  const int64_t kmax = config_.log2_max_probes;
  int64_t k = unbounded ? kmax : std::min(kmax, (rho + (int64_t{1} << (g - 1))) >> g);
  const int64_t e = static_cast<int64_t>(std::bit_width(smax)) - 1;
  const int64_t floor_log2_rmax = (e + 2 * sh - 2 * kFastFpPortFrac) >> 1;
  k = std::min(k, std::max<int64_t>(0, floor_log2_rmax + 2));
  p.log2_n = static_cast<int>(k);

  const int64_t spread = log2_rmax - (k << g);
  const int64_t lambda_g = unbounded ? spread : std::max(log2_q, spread);
  const int64_t lambda =
      g >= kFastFpPortFrac
          ? (lambda_g + (g > kFastFpPortFrac ? int64_t{1} << (g - kFastFpPortFrac - 1) : 0)) >>
                (g - kFastFpPortFrac)
          : lambda_g << (kFastFpPortFrac - g);
  p.lambda = static_cast<int32_t>(std::clamp<int64_t>(lambda, kLambdaMin, kLambdaMax));
  return p;
}

uint32_t FastFootprint::sample(const Request& r) const {
  const Plan p = plan(r);
  const texram::SamplerConfig& sampler = unit_.config();
  const int k = p.log2_n, n = 1 << k;
  const int64_t du = p.r2_longer ? r.r2u : r.r1u;
  const int64_t dv = p.r2_longer ? r.r2v : r.r1v;
  // Probe i at ((c << (k + 1)) + n d + 2^k) >> (k + 1), n = 2i - (N - 1): n steps by 2.
  const int64_t first_n = 1 - int64_t{n};
  int64_t pu = (int64_t{r.u} << (k + 1)) + first_n * du + (int64_t{1} << k);
  int64_t pv = (int64_t{r.v} << (k + 1)) + first_n * dv + (int64_t{1} << k);
  std::array<int32_t, kMaxProbes> u, v;
  for (int i = 0; i < n; ++i) {
    u[static_cast<size_t>(i)] = fast_to_port(pu >> (k + 1), sampler.border_u);
    v[static_cast<size_t>(i)] = fast_to_port(pv >> (k + 1), sampler.border_v);
    pu += 2 * du;
    pv += 2 * dv;
  }
  std::array<uint32_t, kMaxProbes> colours;
  unit_.sample_points(unit_.levels(p.lambda), u.data(), v.data(), n, r.shade, colours.data());
  // The colours summed in 16-bit lanes: at most 16 * 255 + 8 < 2^16.
  uint64_t sum = 0;
  for (int i = 0; i < n; ++i) sum += texram::spread16(colours[static_cast<size_t>(i)]);
  // (sum + N/2) >> k per lane; bits shifted in from the lane above land above bit 7.
  const uint64_t half = k > 0 ? uint64_t{1} << (k - 1) : 0;
  return texram::pack16((sum + half * 0x0001000100010001ull) >> k);
}

void FastFootprint::sample_batch(std::span<const Request> requests, std::span<uint32_t> out) const {
  if (out.size() != requests.size()) {
    throw std::invalid_argument("FastFootprint::sample_batch: " + std::to_string(out.size()) +
                                " results for " + std::to_string(requests.size()) + " requests");
  }
  for (size_t i = 0; i < requests.size(); ++i) out[i] = sample(requests[i]);
}

}  // namespace tmu::footprint
