#include "clipmap/clipmap_ideal.hpp"

#include <algorithm>
#include <cmath>

namespace tmu::clipmap::ideal {
namespace {

using texram::Border;
using texram::Filter;
using Colour = std::array<double, 4>;

Colour unpack(uint32_t rgba) {
  return {double(rgba >> 24), double((rgba >> 16) & 0xFF), double((rgba >> 8) & 0xFF),
          double(rgba & 0xFF)};
}

struct Texel {
  bool outside = false;  // border colour: reads nothing
  int64_t x = 0;         // the resolved texel of its level
};

// The border operator on texel x of a virtual level n texels wide.
Texel resolve(int64_t x, int64_t n, Border b) {
  switch (b) {
    case Border::kWrap:
      return {false, ((x % n) + n) % n};
    case Border::kClamp:
      return {false, std::clamp<int64_t>(x, 0, n - 1)};
    case Border::kMirror: {
      const int64_t m = ((x % (2 * n)) + 2 * n) % (2 * n);
      return {false, m < n ? m : 2 * n - 1 - m};
    }
    case Border::kBorder:
      return {x < 0 || x >= n, x};
  }
  return {true, 0};
}

struct Tap {
  int level;
  Texel x, y;
};

bool held(const Setup& s, int level, const Tap& t) {
  if (level >= s.log2_virtual - s.log2_tile || t.x.outside || t.y.outside) return true;
  const Tile& r = s.tiles[static_cast<size_t>(level)];
  return t.x.x >= r.x0 && t.x.x < r.x1 && t.y.x >= r.y0 && t.y.x < r.y1;
}

// The taps of the point (u, v) at a level: x0y0, x1y0, x0y1, x1y1 (nearest: the first), and
// the second's exact weights.
struct Footprint {
  std::array<Tap, 4> taps;
  int count;
  double fx, fy;
};
Footprint footprint(const Setup& s, const texram::SamplerConfig& c, int level, double u, double v) {
  const double ul = std::ldexp(u, -level), vl = std::ldexp(v, -level);
  const int64_t n = int64_t{1} << (s.log2_virtual - level);
  Footprint f{};
  const bool nearest = c.filter == Filter::kNearest;
  const double sx = nearest ? ul : ul - 0.5, sy = nearest ? vl : vl - 0.5;
  const auto x0 = static_cast<int64_t>(std::floor(sx)), y0 = static_cast<int64_t>(std::floor(sy));
  f.fx = sx - std::floor(sx);
  f.fy = sy - std::floor(sy);
  f.count = nearest ? 1 : 4;
  for (int k = 0; k < f.count; ++k) {
    f.taps[static_cast<size_t>(k)] = {level, resolve(x0 + (k & 1), n, c.border_u),
                                      resolve(y0 + (k >> 1), n, c.border_v)};
  }
  return f;
}

bool holds_point(const Setup& s, const Footprint& f) {
  for (int k = 0; k < f.count; ++k) {
    if (!held(s, f.taps[static_cast<size_t>(k)].level, f.taps[static_cast<size_t>(k)]))
      return false;
  }
  return true;
}

Colour texel_colour(const texram::IdealTexture& t, const texram::SamplerConfig& c, const Setup& s,
                    Tap tap) {
  if (tap.x.outside || tap.y.outside) return unpack(c.border_rgba);
  if (s.per_tap) {  // the first coarser tile that holds the location
    while (!held(s, tap.level, tap)) {
      ++tap.level;
      tap.x.x /= 2;
      tap.y.x /= 2;
    }
  }
  return texram::ideal_texel(t, c, tap.level, static_cast<uint32_t>(tap.x.x),
                             static_cast<uint32_t>(tap.y.x));
}

Colour level_colour(const texram::IdealTexture& t, const texram::SamplerConfig& c, const Setup& s,
                    const Footprint& f) {
  if (f.count == 1) return texel_colour(t, c, s, f.taps[0]);
  Colour out{};
  const double w[4] = {(1 - f.fx) * (1 - f.fy), f.fx * (1 - f.fy), (1 - f.fx) * f.fy, f.fx * f.fy};
  for (size_t k = 0; k < 4; ++k) {
    const Colour tc = texel_colour(t, c, s, f.taps[k]);
    for (size_t ch = 0; ch < 4; ++ch) out[ch] += w[k] * tc[ch];
  }
  return out;
}

}  // namespace

Colour sample(const texram::IdealTexture& t, const texram::SamplerConfig& c, const Setup& s,
              double u, double v, double lambda, uint32_t shade) {
  const int top = s.log2_virtual;
  // The levels and the second's weight, exactly (trilinear), or the rounded level.
  int l0 = 0, l1 = 0;
  double wl = 0;
  if (c.filter == Filter::kTrilinear) {
    const double lc = std::clamp(lambda, 0.0, double(top));
    l0 = static_cast<int>(std::floor(lc));
    l1 = std::min(l0 + 1, top);
    wl = lc - l0;
  } else {
    l0 = l1 = static_cast<int>(std::clamp(std::floor(lambda + 0.5), 0.0, double(top)));
  }
  if (!s.per_tap) {
    const bool two = wl > 0;
    const bool as_is = holds_point(s, footprint(s, c, l0, u, v)) &&
                       (!two || holds_point(s, footprint(s, c, l1, u, v)));
    if (!as_is) {
      int m = l0 + 1;
      while (!holds_point(s, footprint(s, c, m, u, v))) ++m;  // a whole level holds
      l0 = l1 = m;
      wl = 0;
    }
  }
  const Colour a = level_colour(t, c, s, footprint(s, c, l0, u, v));
  Colour out = a;
  if (wl > 0) {
    const Colour b = level_colour(t, c, s, footprint(s, c, l1, u, v));
    for (size_t ch = 0; ch < 4; ++ch) out[ch] = a[ch] * (1 - wl) + b[ch] * wl;
  }
  if (c.combine != texram::Combine::kOne) {
    const Colour m = unpack(c.combine == texram::Combine::kConstant ? c.constant_rgba : shade);
    for (size_t ch = 0; ch < 4; ++ch) out[ch] = out[ch] * m[ch] / 255;
  }
  return out;
}

}  // namespace tmu::clipmap::ideal
