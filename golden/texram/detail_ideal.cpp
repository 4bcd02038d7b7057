#include "texram/detail_ideal.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace tmu::texram {
namespace {

// The level-0 texel nearest coordinate c (floor) on an axis of n texels under the texture's
// border operator; none outside a border-mode texture.
std::optional<uint32_t> nearest_texel(double c, uint32_t n, Border border) {
  const auto x = static_cast<int64_t>(std::floor(c));
  const auto nn = static_cast<int64_t>(n);
  switch (border) {
    case Border::kWrap:
      return static_cast<uint32_t>(((x % nn) + nn) % nn);
    case Border::kClamp:
      return static_cast<uint32_t>(std::clamp<int64_t>(x, 0, nn - 1));
    case Border::kMirror: {
      const int64_t m = ((x % (2 * nn)) + 2 * nn) % (2 * nn);
      return static_cast<uint32_t>(m < nn ? m : 2 * nn - 1 - m);
    }
    case Border::kBorder:
      if (x < 0 || x >= nn) return std::nullopt;
      return static_cast<uint32_t>(x);
  }
  return std::nullopt;
}

}  // namespace

IdealDetailMap ideal_detail_map(const SourceTexels& detail, const Level8& offset_u,
                                const Level8& offset_v) {
  if (offset_u.width != offset_v.width || offset_u.height != offset_v.height) {
    throw std::invalid_argument("ideal_detail_map: the offset maps differ in size");
  }
  return {ideal_texture(detail), offset_u, offset_v};
}

std::array<double, 4> ideal_detail_sample(const IdealTexture& texture, const SamplerConfig& config,
                                          const IdealDetailMap& map, DetailCombine combine,
                                          double u, double v, double lambda, uint32_t shade) {
  if (lambda >= 0) return ideal_sample(texture, config, u, v, lambda, shade);
  // 1. The region of the nearest level-0 texel.
  const auto x = nearest_texel(u, map.offset_u.width, config.border_u);
  const auto y = nearest_texel(v, map.offset_u.height, config.border_v);
  if (!x || !y) return ideal_sample(texture, config, u, v, 0.0, shade);  // no texel, no region
  const double ou = map.offset_u.at(*x, *y), ov = map.offset_v.at(*x, *y);
  // 2. The detail: the region's point at lambda + 4, level -1 (3) between -1 and 0.
  SamplerConfig dc;
  dc.kind = map.detail.kind;
  dc.single_channel = config.single_channel;
  dc.filter = Filter::kTrilinear;
  dc.border_u = dc.border_v = Border::kWrap;
  const double side = kDetailRegionSide;
  const double ud = ou + side * (u - std::floor(u)), vd = ov + side * (v - std::floor(v));
  const double f = lambda > -1 ? lambda + 1 : 0.0;  // the texture's level 0's share
  const double lambda_d = lambda > -1 ? kDetailLevels - 1 : lambda + kDetailLevels;
  const auto d = ideal_sample(map.detail, dc, ud, vd, lambda_d);
  // 3. The texture's level 0 under its own filter and borders.
  SamplerConfig tc = config;
  tc.combine = Combine::kOne;
  const auto t = ideal_sample(texture, tc, u, v, 0.0);
  std::array<double, 4> out{};
  for (size_t c = 0; c < 4; ++c) {
    const double base = combine == DetailCombine::kModulate
                            ? (c == 3 ? t[c] : std::min(255.0, t[c] * d[c] / 128.0))
                            : d[c];
    out[c] = (1 - f) * base + f * t[c];
  }
  if (config.combine != Combine::kOne) {
    const uint32_t m = config.combine == Combine::kConstant ? config.constant_rgba : shade;
    for (int c = 0; c < 4; ++c) out[static_cast<size_t>(c)] *= channel(m, c) / 255.0;
  }
  return out;
}

}  // namespace tmu::texram
