#include "texram/fast_trilinear.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "formats/formats.hpp"
#include "texram/rgba_lanes.hpp"
#include "texram/trilinear.hpp"

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

}  // namespace

// The sample loops. K fixes what is constant for a sampler: nearest or not, the border modes,
// and whether the widths are all 8 (then every shift below is a constant).
template <bool kNearest, Border kBu, Border kBv, bool kW8>
struct FastKind {
  static constexpr bool nearest = kNearest;
  static constexpr Border bu = kBu, bv = kBv;
  static constexpr bool w8 = kW8;
};

struct FastTrilinear::Kernels {
  // The border operator onto the prepared level's -1..n: the golden's resolve_border, except
  // that border mode's outside becomes -1 or n (the margin, holding the border colour) instead
  // of a flag. n is a power of two.
  template <Border B>
  static int64_t resolve(int64_t x, int64_t n) {
    if constexpr (B == Border::kWrap) return x & (n - 1);
    if constexpr (B == Border::kClamp) return std::clamp<int64_t>(x, 0, n - 1);
    if constexpr (B == Border::kMirror) {
      const int64_t m = x & (2 * n - 1);
      return m < n ? m : 2 * n - 1 - m;
    }
    if constexpr (B == Border::kBorder) return std::clamp<int64_t>(x, -1, n);
    return 0;
  }

  // choose_levels: nearest and bilinear the one level round(lambda), trilinear floor(lambda)
  // and the next weighed by the fraction. (K tells nearest from the rest; trilinear and
  // bilinear share their loops, so the filter is read from the configuration.)
  template <class K>
  static FastLevels levels(const FastTrilinear& t, int32_t request_lambda) {
    const Widths& w = t.config_.widths;
    const int lod_frac = K::w8 ? 8 : w.lod_frac, weight = K::w8 ? 8 : w.weight;
    const int lod_drop = kFastLodFrac - lod_frac;
    const int64_t lambda = (int64_t{request_lambda} >> lod_drop) << lod_drop;
    FastLevels f;
    if (!K::nearest && t.config_.filter == Filter::kTrilinear) {
      const uint32_t one = uint32_t{1} << weight;
      uint32_t wl = 0;
      if (lambda <= 0) {
        f.level = {0, 0};  // magnification: level 0, the second level weighs nothing
      } else if (lambda >= int64_t{t.top_} << kFastLodFrac) {
        f.level = {t.top_, t.top_};
      } else {
        const int l0 = static_cast<int>(lambda >> kFastLodFrac);
        f.level = {l0, l0 + 1};
        const auto frac = static_cast<uint32_t>(lambda & ((1 << kFastLodFrac) - 1)) >> lod_drop;
        wl = lod_frac >= weight ? frac >> (lod_frac - weight) : frac << (weight - lod_frac);
      }
      f.count = wl != 0 ? 2 : 1;  // a level of weight 0 is not read
      f.lw = {one - wl, wl};
      f.drop = 3 * weight;
    } else {
      const int64_t d = (lambda + (1 << (kFastLodFrac - 1))) >> kFastLodFrac;
      const int level = static_cast<int>(std::clamp<int64_t>(d, 0, t.top_));
      f.level = {level, level};
      f.lw = {1, 0};
      f.drop = 2 * weight;
    }
    return f;
  }

  // The filtered texture value at port coordinates (u, v) (after texel_request).
  template <class K>
  static uint32_t filter(const FastTrilinear& t, const FastLevels& f, int32_t u, int32_t v) {
    if constexpr (K::nearest) {  // axis_taps: floor at the level
      const Level& L = t.level_[static_cast<size_t>(f.level[0])];
      const int shift = kFastPortFrac + f.level[0];
      return pack16(L.origin[resolve<K::bv>(int64_t{v} >> shift, L.h) * L.stride +
                             resolve<K::bu>(int64_t{u} >> shift, L.w)]);
    } else {
      const Widths& w = t.config_.widths;
      const int s = K::w8 ? 8 : w.sub_texel;
      const int weight = K::w8 ? 8 : w.weight;
      const int64_t half_texel = int64_t{1} << (s - 1);
      const int64_t frac_mask = (int64_t{1} << s) - 1;
      // A sub-texel fraction as a W-bit weight (to_width): one of the two shifts is zero.
      const int up = s < weight ? weight - s : 0, down = s > weight ? s - weight : 0;
      const uint64_t one = uint64_t{1} << weight;
      uint64_t acc_rb = 0, acc_ga = 0;  // R, B and G, A in 32-bit lanes
      for (size_t j = 0; j < static_cast<size_t>(f.count); ++j) {
        const Level& L = t.level_[static_cast<size_t>(f.level[j])];
        // axis_taps: the coordinate rounded half up to S fraction bits, minus half a texel.
        const int cd = K::w8 ? f.level[j] : L.coord_drop;
        const int64_t round = (int64_t{1} << cd) >> 1;
        const int64_t su = ((int64_t{u} + round) >> cd) - half_texel;
        const int64_t sv = ((int64_t{v} + round) >> cd) - half_texel;
        const int64_t tu = su >> s, tv = sv >> s;
        const uint64_t wx = static_cast<uint64_t>((su & frac_mask) << up) >> down;
        const uint64_t wy = static_cast<uint64_t>((sv & frac_mask) << up) >> down;
        const int64_t x0 = resolve<K::bu>(tu, L.w), x1 = resolve<K::bu>(tu + 1, L.w);
        const uint64_t* r0 = L.origin + resolve<K::bv>(tv, L.h) * L.stride;
        const uint64_t* r1 = L.origin + resolve<K::bv>(tv + 1, L.h) * L.stride;
        // Each row's two taps in 16-bit lanes: at most 255 * 2^W <= 65280.
        const uint64_t h0 = r0[x0] * (one - wx) + r0[x1] * wx;
        const uint64_t h1 = r1[x0] * (one - wx) + r1[x1] * wx;
        // The rows and the level weight in 32-bit lanes: at most 255 * 2^3W < 2^32.
        const uint64_t w0 = (one - wy) * f.lw[j], w1 = wy * f.lw[j];
        acc_ga += (h0 & kLow32Lanes) * w0 + (h1 & kLow32Lanes) * w1;
        acc_rb += (h0 >> 16 & kLow32Lanes) * w0 + (h1 >> 16 & kLow32Lanes) * w1;
      }
      // One rounding, half up, per channel (every sum is non-negative; + half stays < 2^32).
      const uint64_t half = uint64_t{1} << (f.drop - 1);
      const uint64_t halves = half | half << 32;
      return pack32((acc_rb + halves) >> f.drop, (acc_ga + halves) >> f.drop);
    }
  }

  // Eq. 5 (combine): multiplying by one, the common case, is no work.
  static uint32_t combine(const SamplerConfig& c, uint32_t t, uint32_t shade) {
    return c.combine == Combine::kOne ? t : multiply(c, t, shade);
  }
  static uint32_t multiply(const SamplerConfig& c, uint32_t t, uint32_t shade) {
    const uint32_t m = c.combine == Combine::kConstant ? c.constant_rgba : shade;
    uint32_t out = 0;
    for (int i = 0; i < 4; ++i) out |= mul255(channel(t, i), channel(m, i)) << (24 - 8 * i);
    return out;
  }

  // One sample: texel_request, levels, filter, combine.
  template <class K>
  static uint32_t sample(const FastTrilinear& t, const FastLevels& f, Request r) {
    if (t.config_.addressing != Addressing::kTexel) {
      r = texel_request(t.geometry_, t.config_.addressing, r);
    }
    return combine(t.config_, filter<K>(t, f, r.u, r.v), r.shade);
  }

  template <class K>
  static void batch(const FastTrilinear& t, std::span<const Request> rs, std::span<uint32_t> out) {
    for (size_t i = 0; i < rs.size(); ++i) out[i] = sample<K>(t, levels<K>(t, rs[i].lambda), rs[i]);
  }

  template <class K>
  static void points(const FastTrilinear& t, const FastLevels& f, const int32_t* u,
                     const int32_t* v, int n, uint32_t shade, uint32_t* out) {
    for (int i = 0; i < n; ++i) out[i] = sample<K>(t, f, Request{u[i], v[i], 0, shade});
  }

  // Binds the loops of the sampler's configuration class: runtime values to template ones.
  template <bool kNearest, Border kBu, Border kBv>
  static void bind_widths(FastTrilinear& t, bool w8) {
    if (w8 && !kNearest) {
      t.batch_ = &batch<FastKind<kNearest, kBu, kBv, true>>;
      t.points_ = &points<FastKind<kNearest, kBu, kBv, true>>;
    } else {
      t.batch_ = &batch<FastKind<kNearest, kBu, kBv, false>>;
      t.points_ = &points<FastKind<kNearest, kBu, kBv, false>>;
    }
  }
  template <bool kNearest, Border kBu>
  static void bind_v(FastTrilinear& t, Border bv, bool w8) {
    switch (bv) {
      case Border::kWrap:
        return bind_widths<kNearest, kBu, Border::kWrap>(t, w8);
      case Border::kClamp:
        return bind_widths<kNearest, kBu, Border::kClamp>(t, w8);
      case Border::kBorder:
        return bind_widths<kNearest, kBu, Border::kBorder>(t, w8);
      case Border::kMirror:
        return bind_widths<kNearest, kBu, Border::kMirror>(t, w8);
    }
  }
  template <bool kNearest>
  static void bind_u(FastTrilinear& t, Border bu, Border bv, bool w8) {
    switch (bu) {
      case Border::kWrap:
        return bind_v<kNearest, Border::kWrap>(t, bv, w8);
      case Border::kClamp:
        return bind_v<kNearest, Border::kClamp>(t, bv, w8);
      case Border::kBorder:
        return bind_v<kNearest, Border::kBorder>(t, bv, w8);
      case Border::kMirror:
        return bind_v<kNearest, Border::kMirror>(t, bv, w8);
    }
  }
  static void bind(FastTrilinear& t) {
    const SamplerConfig& c = t.config_;
    const bool w8 = c.widths == Widths{8, 8, 8};
    if (c.filter == Filter::kNearest) {
      bind_u<true>(t, c.border_u, c.border_v, w8);
    } else {
      bind_u<false>(t, c.border_u, c.border_v, w8);
    }
  }
};

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
  texels_.assign(total, spread16(config.border_rgba));
  size_t at = 0;
  for (int l = 0; l <= top_; ++l) {
    Level& L = level_[static_cast<size_t>(l)];
    L.w = g.texel_width(l);
    L.h = g.texel_height(l);
    L.stride = L.w + 2;
    uint64_t* origin = texels_.data() + at + L.stride + 1;
    L.origin = origin;
    L.coord_drop = kFastPortFrac - w.sub_texel + l;
    for (uint32_t y = 0; y < L.h; ++y) {
      for (uint32_t x = 0; x < L.w; ++x) {
        origin[y * L.stride + x] = spread16(texel_rgba(texture, config, l, x, y));
      }
    }
    at += static_cast<size_t>(L.stride * (L.h + 2));
  }
  Kernels::bind(*this);
}

FastLevels FastTrilinear::levels(int32_t lambda) const {
  return config_.filter == Filter::kNearest
             ? Kernels::levels<FastKind<true, Border::kWrap, Border::kWrap, false>>(*this, lambda)
             : Kernels::levels<FastKind<false, Border::kWrap, Border::kWrap, false>>(*this, lambda);
}

void FastTrilinear::sample_batch(std::span<const Request> requests, std::span<uint32_t> out) const {
  if (out.size() != requests.size()) {
    throw std::invalid_argument("FastTrilinear::sample_batch: " + std::to_string(out.size()) +
                                " results for " + std::to_string(requests.size()) + " requests");
  }
  batch_(*this, requests, out);
}

}  // namespace tmu::texram
