#include "texram/trilinear_ideal.hpp"

#include <algorithm>
#include <cmath>

#include "texram/trilinear.hpp"

namespace tmu::texram {
namespace {

struct Resolved {
  bool outside;
  uint32_t x;
};

Resolved resolve(double xf, uint32_t n, Border border) {
  const auto x = static_cast<int64_t>(xf);  // xf is an integer value
  const auto nn = static_cast<int64_t>(n);
  switch (border) {
    case Border::kWrap:
      return {false, static_cast<uint32_t>(((x % nn) + nn) % nn)};
    case Border::kClamp:
      return {false, static_cast<uint32_t>(std::clamp<int64_t>(x, 0, nn - 1))};
    case Border::kMirror: {
      const int64_t m = ((x % (2 * nn)) + 2 * nn) % (2 * nn);
      return {false, static_cast<uint32_t>(m < nn ? m : 2 * nn - 1 - m)};
    }
    case Border::kBorder:
      return {x < 0 || x >= nn, static_cast<uint32_t>(std::clamp<int64_t>(x, 0, nn - 1))};
  }
  return {true, 0};
}

std::array<double, 4> unpack(uint32_t c) {
  return {double(channel(c, 0)), double(channel(c, 1)), double(channel(c, 2)),
          double(channel(c, 3))};
}

std::array<double, 4> level_sample(const TexramTexture& t, const SamplerConfig& config, double u,
                                   double v, int l, bool nearest) {
  const double scale = std::ldexp(1.0, -l);
  const double ul = u * scale, vl = v * scale;
  const Geometry& g = t.geometry;
  auto texel = [&](double x, double y) {
    const Resolved rx = resolve(x, g.texel_width(l), config.border_u);
    const Resolved ry = resolve(y, g.texel_height(l), config.border_v);
    if (rx.outside || ry.outside) return unpack(config.border_rgba);
    return unpack(texel_rgba(t, config, l, rx.x, ry.x));
  };
  if (nearest) return texel(std::floor(ul), std::floor(vl));
  const double sx = ul - 0.5, sy = vl - 0.5;
  const double x0 = std::floor(sx), y0 = std::floor(sy);
  const double fx = sx - x0, fy = sy - y0;
  const auto c00 = texel(x0, y0), c10 = texel(x0 + 1, y0), c01 = texel(x0, y0 + 1),
             c11 = texel(x0 + 1, y0 + 1);
  std::array<double, 4> out{};
  for (size_t c = 0; c < 4; ++c) {
    out[c] = (c00[c] * (1 - fx) + c10[c] * fx) * (1 - fy) + (c01[c] * (1 - fx) + c11[c] * fx) * fy;
  }
  return out;
}

}  // namespace

uint32_t texel_rgba(const TexramTexture& t, const SamplerConfig& config, int level, uint32_t x,
                    uint32_t y) {
  const Geometry& g = t.geometry;
  Tap tap;
  tap.x = x;
  tap.y = y;
  tap.cell = g.block_grid() ? g.cell(level, x >> 2, y >> 2) : g.cell(level, x, y);
  AccessData data{};
  for (int p = 0; p < g.planes(); ++p) {
    data[tap.cell.bank][static_cast<size_t>(p)] =
        t.banks[tap.cell.bank][tap.cell.address + static_cast<uint32_t>(p)];
  }
  return tap_colour(tap, data, t.kind, config, t.clut);
}

std::array<double, 4> ideal_sample(const TexramTexture& t, const SamplerConfig& config, double u,
                                   double v, double lambda, uint32_t shade) {
  const int top = t.geometry.levels() - 1;
  std::array<double, 4> out{};
  if (config.filter == Filter::kTrilinear) {
    const double lc = std::clamp(lambda, 0.0, double(top));
    const int l0 = std::min(static_cast<int>(std::floor(lc)), top);
    const double f = lc - l0;
    const auto a = level_sample(t, config, u, v, l0, false);
    const auto b = f > 0 ? level_sample(t, config, u, v, std::min(l0 + 1, top), false) : a;
    for (size_t c = 0; c < 4; ++c) out[c] = a[c] * (1 - f) + b[c] * f;
  } else {
    const int d = static_cast<int>(std::clamp(std::floor(lambda + 0.5), 0.0, double(top)));
    out = level_sample(t, config, u, v, d, config.filter == Filter::kNearest);
  }
  if (config.combine != Combine::kOne) {
    const uint32_t m = config.combine == Combine::kConstant ? config.constant_rgba : shade;
    for (int c = 0; c < 4; ++c) out[static_cast<size_t>(c)] *= channel(m, c) / 255.0;
  }
  return out;
}

}  // namespace tmu::texram
