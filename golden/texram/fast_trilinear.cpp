#include "texram/fast_trilinear.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "formats/formats.hpp"

namespace tmu::texram {
namespace {

constexpr int kFastPortFrac = formats::kTexCoord.frac_bits;  // 8
constexpr int kFastLodFrac = formats::kLod.frac_bits;        // 8

// The golden reads a replica cell of a level one grid cell wide (or high) by the tap's parity;
// the prepared texture keeps one copy, which is exact only if the replicas agree.
void check_replicas(const TexramTexture& t) {
  const Geometry& g = t.geometry;
  for (int l = 0; l < g.levels(); ++l) {
    const uint32_t gw = g.grid_width(l), gh = g.grid_height(l);
    if (gw > 1 && gh > 1) continue;
    for (uint32_t y = 0; y < g.stored_height(l); ++y) {
      for (uint32_t x = 0; x < g.stored_width(l); ++x) {
        for (int p = 0; p < g.planes(); ++p) {
          if (t.cell(l, x, y, p) != t.cell(l, x % gw, y % gh, p)) {
            throw std::invalid_argument("FastTrilinear: replica cell (" + std::to_string(x) + ", " +
                                        std::to_string(y) + ") of level " + std::to_string(l) +
                                        " differs from its original");
          }
        }
      }
    }
  }
}

// The border operator on a tap coordinate, onto the prepared level's -1..n: the golden's
// resolve_border, except that border mode's outside becomes -1 or n (the margin, which holds
// the border colour) instead of a flag. n is a power of two.
inline int64_t resolve_fast(int64_t x, int64_t n, Border border) {
  switch (border) {
    case Border::kWrap:
      return x & (n - 1);
    case Border::kClamp:
      return std::clamp<int64_t>(x, 0, n - 1);
    case Border::kMirror: {
      const int64_t m = x & (2 * n - 1);
      return m < n ? m : 2 * n - 1 - m;
    }
    case Border::kBorder:
      return std::clamp<int64_t>(x, -1, n);
  }
  return 0;
}

// RGBA8888 spread to four 16-bit lanes: R in 63:48, G 47:32, B 31:16, A 15:0.
inline uint64_t spread16(uint32_t c) {
  uint64_t x = c;
  x = (x | x << 16) & 0x0000FFFF0000FFFFull;
  return (x | x << 8) & 0x00FF00FF00FF00FFull;
}

constexpr uint64_t kLanes32 = 0x0000FFFF0000FFFFull;  // the low halves of two 32-bit lanes

}  // namespace

FastTrilinear::FastTrilinear(const TexramTexture& texture, const SamplerConfig& config)
    : config_(config), geometry_(texture.geometry) {
  const Widths& w = config.widths;
  const auto ok = [](int b) { return b >= 1 && b <= 8; };
  if (!ok(w.sub_texel) || !ok(w.weight) || !ok(w.lod_frac)) {
    throw std::invalid_argument("texram widths must be 1..8 bits");
  }
  check_replicas(texture);
  const Geometry& g = texture.geometry;
  top_ = g.levels() - 1;
  size_t total = 0;
  for (int l = 0; l <= top_; ++l) total += (g.texel_width(l) + 2) * size_t{g.texel_height(l) + 2};
  texels_.assign(total, config.border_rgba);
  size_t at = 0;
  for (int l = 0; l <= top_; ++l) {
    Level& L = level_[static_cast<size_t>(l)];
    L.w = g.texel_width(l);
    L.h = g.texel_height(l);
    L.stride = L.w + 2;
    uint32_t* origin = texels_.data() + at + L.stride + 1;
    L.origin = origin;
    L.coord_drop = kFastPortFrac - w.sub_texel + l;
    for (uint32_t y = 0; y < L.h; ++y) {
      for (uint32_t x = 0; x < L.w; ++x) {
        origin[y * L.stride + x] = texel_rgba(texture, config, l, x, y);
      }
    }
    at += static_cast<size_t>(L.stride * (L.h + 2));
  }
}

FastLevels FastTrilinear::levels(int32_t request_lambda) const {
  const Widths& w = config_.widths;
  const int lod_drop = kFastLodFrac - w.lod_frac;
  const int64_t lambda = (int64_t{request_lambda} >> lod_drop) << lod_drop;
  FastLevels f;
  if (config_.filter == Filter::kTrilinear) {
    const uint32_t one = uint32_t{1} << w.weight;
    uint32_t wl = 0;
    if (lambda <= 0) {
      f.level = {0, 0};
    } else if (lambda >= int64_t{top_} << kFastLodFrac) {
      f.level = {top_, top_};
    } else {
      const int l0 = static_cast<int>(lambda >> kFastLodFrac);
      f.level = {l0, l0 + 1};
      const auto frac = static_cast<uint32_t>(lambda & ((1 << kFastLodFrac) - 1)) >> lod_drop;
      wl = w.lod_frac >= w.weight ? frac >> (w.lod_frac - w.weight)
                                  : frac << (w.weight - w.lod_frac);
    }
    f.count = wl != 0 ? 2 : 1;
    f.lw = {one - wl, wl};
    f.drop = 3 * w.weight;
  } else {
    const int64_t d = (lambda + (1 << (kFastLodFrac - 1))) >> kFastLodFrac;
    const int level = static_cast<int>(std::clamp<int64_t>(d, 0, top_));
    f.level = {level, level};
    f.lw = {1, 0};
    f.drop = 2 * w.weight;
  }
  return f;
}

uint32_t FastTrilinear::nearest(int level, int32_t u, int32_t v) const {
  const Level& L = level_[static_cast<size_t>(level)];
  const int shift = kFastPortFrac + level;
  const int64_t x = resolve_fast(int64_t{u} >> shift, L.w, config_.border_u);
  const int64_t y = resolve_fast(int64_t{v} >> shift, L.h, config_.border_v);
  return L.origin[y * L.stride + x];
}

uint32_t FastTrilinear::bilinear(const FastLevels& f, int32_t u, int32_t v) const {
  const Widths& w = config_.widths;
  const int s = w.sub_texel;
  const int64_t half_texel = int64_t{1} << (s - 1);
  const int64_t frac_mask = (int64_t{1} << s) - 1;
  // A sub-texel fraction as a W-bit weight (to_width): one of the two shifts is zero.
  const int up = s < w.weight ? w.weight - s : 0, down = s > w.weight ? s - w.weight : 0;
  const uint64_t one = uint64_t{1} << w.weight;
  uint64_t acc_rb = 0, acc_ga = 0;  // R, B and G, A in 32-bit lanes
  for (int j = 0; j < f.count; ++j) {
    const Level& L = level_[static_cast<size_t>(f.level[static_cast<size_t>(j)])];
    // axis_taps: the coordinate rounded half up to S fraction bits, minus half a texel.
    const int cd = L.coord_drop;
    const int64_t round = cd > 0 ? int64_t{1} << (cd - 1) : 0;
    const int64_t su = ((int64_t{u} + round) >> cd) - half_texel;
    const int64_t sv = ((int64_t{v} + round) >> cd) - half_texel;
    const int64_t tu = su >> s, tv = sv >> s;
    const uint64_t wx = static_cast<uint64_t>((su & frac_mask) << up) >> down;
    const uint64_t wy = static_cast<uint64_t>((sv & frac_mask) << up) >> down;
    const int64_t x0 = resolve_fast(tu, L.w, config_.border_u);
    const int64_t x1 = resolve_fast(tu + 1, L.w, config_.border_u);
    const uint32_t* row0 = L.origin + resolve_fast(tv, L.h, config_.border_v) * L.stride;
    const uint32_t* row1 = L.origin + resolve_fast(tv + 1, L.h, config_.border_v) * L.stride;
    // Each row's two taps in 16-bit lanes: at most 255 * 2^W <= 65280.
    const uint64_t h0 = spread16(row0[x0]) * (one - wx) + spread16(row0[x1]) * wx;
    const uint64_t h1 = spread16(row1[x0]) * (one - wx) + spread16(row1[x1]) * wx;
    // The rows and the level weight in 32-bit lanes: at most 255 * 2^3W < 2^32.
    const uint64_t w0 = (one - wy) * f.lw[static_cast<size_t>(j)];
    const uint64_t w1 = wy * f.lw[static_cast<size_t>(j)];
    acc_ga += (h0 & kLanes32) * w0 + (h1 & kLanes32) * w1;
    acc_rb += (h0 >> 16 & kLanes32) * w0 + (h1 >> 16 & kLanes32) * w1;
  }
  // One rounding, half up, per channel (every sum is non-negative).
  const uint64_t half = uint64_t{1} << (f.drop - 1);
  const uint64_t halves = half | half << 32;
  const uint64_t rb = ((acc_rb + halves) >> f.drop) & 0x000000FF000000FFull;
  const uint64_t ga = ((acc_ga + halves) >> f.drop) & 0x000000FF000000FFull;
  return static_cast<uint32_t>((rb >> 32) << 24 | (ga >> 32) << 16 | (rb & 0xFF) << 8 |
                               (ga & 0xFF));
}

uint32_t FastTrilinear::combine_fast(uint32_t t, uint32_t shade) const {
  if (config_.combine == Combine::kOne) return t;
  const uint32_t m = config_.combine == Combine::kConstant ? config_.constant_rgba : shade;
  uint32_t out = 0;
  for (int c = 0; c < 4; ++c) out |= mul255(channel(t, c), channel(m, c)) << (24 - 8 * c);
  return out;
}

uint32_t FastTrilinear::sample_at(const FastLevels& f, const Request& port) const {
  int32_t u = port.u, v = port.v;
  if (config_.addressing != Addressing::kTexel) {
    const Request r = texel_request(geometry_, config_.addressing, port);
    u = r.u;
    v = r.v;
  }
  const uint32_t t =
      config_.filter == Filter::kNearest ? nearest(f.level[0], u, v) : bilinear(f, u, v);
  return combine_fast(t, port.shade);
}

void FastTrilinear::sample_batch(std::span<const Request> requests, std::span<uint32_t> out) const {
  if (out.size() != requests.size()) {
    throw std::invalid_argument("FastTrilinear::sample_batch: " + std::to_string(out.size()) +
                                " results for " + std::to_string(requests.size()) + " requests");
  }
  for (size_t i = 0; i < requests.size(); ++i) out[i] = sample(requests[i]);
}

}  // namespace tmu::texram
