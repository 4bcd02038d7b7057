#include "texram/trilinear_ideal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tmu::texram {
namespace {

std::array<double, 4> unpack(uint32_t c) {
  return {double(channel(c, 0)), double(channel(c, 1)), double(channel(c, 2)),
          double(channel(c, 3))};
}

// Byte `x, y` of a level given as bytes (exact integers in double).
uint32_t byte_at(const LevelD& level, uint32_t x, uint32_t y) {
  return static_cast<uint32_t>(level.at(x, y));
}

LevelD as_double(const Level8& l) {
  LevelD d{l.width, l.height, std::vector<double>(l.texels.begin(), l.texels.end())};
  return d;
}

struct Resolved {
  bool outside;
  uint32_t x;
};

// OpenGL's border operators on an integer texel coordinate x of a level n texels wide.
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

std::array<double, 4> level_sample(const IdealTexture& t, const SamplerConfig& config, double u,
                                   double v, int l, bool nearest) {
  const double scale = std::ldexp(1.0, -l);
  const double ul = u * scale, vl = v * scale;
  const uint32_t w = t.width_of(l), h = t.height_of(l);
  auto texel = [&](double x, double y) {
    const Resolved rx = resolve(x, w, config.border_u), ry = resolve(y, h, config.border_v);
    if (rx.outside || ry.outside) return unpack(config.border_rgba);
    return ideal_texel(t, config, l, rx.x, ry.x);
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

IdealTexture ideal_texture(const SourceTexels& s) {
  const auto fail = [](const std::string& why) {
    throw std::invalid_argument("ideal_texture: " + why);
  };
  if (s.planes.empty() || s.planes[0].empty() || s.width == 0 || s.height == 0) fail("no texels");
  const bool coded = s.kind == TexelKind::kIndex || s.kind == TexelKind::kCcc;
  if (s.box_levels && coded) fail("box levels of indices or CCC blocks have no mean");
  IdealTexture t{s.kind, s.width, s.height, s.block_grid, {}, s.clut};
  for (const Pyramid8& plane : s.planes) {
    std::vector<LevelD> levels;
    if (s.box_levels) {
      levels = ideal_pyramid(plane[0]);
    } else {
      for (const Level8& l : plane) levels.push_back(as_double(l));
    }
    t.planes.push_back(std::move(levels));
  }
  for (const auto& levels : t.planes) {
    if (levels.size() != t.planes[0].size()) fail("the planes have different level counts");
    for (size_t l = 0; l < levels.size(); ++l) {
      const int li = static_cast<int>(l);
      const uint32_t w = t.width_of(li), h = t.height_of(li);
      const uint32_t gw = s.block_grid ? (w + 3) / 4 : w, gh = s.block_grid ? (h + 3) / 4 : h;
      if (levels[l].width != gw || levels[l].height != gh)
        fail("level " + std::to_string(l) + " has the wrong size");
    }
  }
  return t;
}

std::array<double, 4> ideal_texel(const IdealTexture& t, const SamplerConfig& config, int level,
                                  uint32_t x, uint32_t y) {
  const auto& p = t.planes;
  const auto l = static_cast<size_t>(level);
  switch (t.kind) {
    case TexelKind::kLuminance: {
      const double v = p[0][l].at(x, y);
      return {v, v, v, 255};
    }
    case TexelKind::kSingle: {  // the component on its channel; alpha 255 unless it is alpha
      std::array<double, 4> c{0, 0, 0, 255};
      c[static_cast<size_t>(config.single_channel)] = p[0][l].at(x, y);
      return c;
    }
    case TexelKind::kIndex:
      return unpack(t.clut[byte_at(p[0][l], x, y)]);
    case TexelKind::kTrueColour:
      return {p[0][l].at(x, y), p[1][l].at(x, y), p[2][l].at(x, y), p[3][l].at(x, y)};
    case TexelKind::kCcc: {
      // The block word (000 §3, Fig. 5): CLUT index a in bits 31:24, b in 23:16, and 16
      // decision bits; bit 4 (y mod 4) + (x mod 4) set takes b for that texel.
      const uint32_t bx = x / 4, by = y / 4;
      const uint32_t bits = byte_at(p[2][l], bx, by) << 8 | byte_at(p[3][l], bx, by);
      const bool take_b = (bits >> (4 * (y % 4) + x % 4)) & 1;
      return unpack(t.clut[byte_at(p[take_b ? 1 : 0][l], bx, by)]);
    }
  }
  return {};
}

std::array<double, 4> ideal_sample(const IdealTexture& t, const SamplerConfig& config, double u,
                                   double v, double lambda, uint32_t shade) {
  const int top = t.levels() - 1;
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
