// What the detail-map suites share (detail_test.cpp, detail_reference_test.cpp): offset maps,
// detail images, the scene of a texture with its detail map and both models' views of it, and
// the comparisons of access records.
#pragma once

#include <random>
#include <utility>
#include <vector>

#include "common/image.hpp"
#include "common/test_patterns.hpp"
#include "texram/detail.hpp"
#include "texram/detail_ideal.hpp"

namespace tmu::texram::detail_test {

inline constexpr int32_t kOne = 256;  // one texel / one level in raw SQ.8
inline constexpr int kSide = kDetailRegionSide;

// --- fixtures ------------------------------------------------------------------------------

// Random offsets, multiples of `step`; the first row is pushed into 240..255 (with step 1) so
// that regions wrap at the detail map's sides.
inline Level8 random_offsets(uint32_t w, uint32_t h, uint32_t step, std::mt19937& rng) {
  Level8 l(w, h);
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const uint32_t o = y == 0 && step == 1 ? 240 + rng() % 16 : rng() % 256;
      l.at(x, y) = static_cast<uint8_t>(o / step * step);
    }
  }
  return l;
}

// A detail image centred at 128 (64..191): the grey micro-structure modulate expects.
inline ImageRgb8 grey_detail(int w, int h, uint32_t seed) {
  ImageRgb8 img = patterns::noise(w, h, seed);
  for (Rgb8& p : img.pixels) {
    p = {static_cast<uint8_t>(64 + p.r / 2), static_cast<uint8_t>(64 + p.g / 2),
         static_cast<uint8_t>(64 + p.b / 2)};
  }
  return img;
}

// A luminance texture of the texels given, its levels the box rule's (the source says so: the
// ideal builds its own exact pyramid).
inline TexramTexture grey_texture(const Level8& texels) {
  ImageRgb8 img(static_cast<int>(texels.width), static_cast<int>(texels.height));
  for (size_t i = 0; i < img.pixels.size(); ++i)
    img.pixels[i] = {texels.texels[i], texels.texels[i], texels.texels[i]};  // luma(v, v, v) = v
  return import_image(img, TexelKind::kLuminance);
}

struct Scene {
  TexramTexture texture;
  DetailMap map;
  IdealTexture ideal_tex;
  IdealDetailMap ideal_map;
};

inline Scene make_scene(TexramTexture texture, TexramTexture detail, const Level8& ou,
                        const Level8& ov) {
  DetailMap map = make_detail_map(std::move(detail), ou, ov);
  IdealTexture it = ideal_texture(texture.source);
  IdealDetailMap im = ideal_detail_map(map.detail.source, map.offset_u.source.planes[0][0],
                                       map.offset_v.source.planes[0][0]);
  return {std::move(texture), std::move(map), std::move(it), std::move(im)};
}

inline SamplerConfig config(TexelKind kind, Filter f = Filter::kTrilinear,
                            Border b = Border::kWrap) {
  SamplerConfig c;
  c.kind = kind;
  c.filter = f;
  c.border_u = c.border_v = b;
  c.border_rgba = rgba(10, 200, 30, 40);
  c.single_channel = 1;
  return c;
}

inline bool same_plan(const SamplePlan& a, const SamplePlan& b) {
  if (a.bank_address != b.bank_address || a.planes != b.planes || a.level != b.level ||
      a.levels_read != b.levels_read || a.taps_per_level != b.taps_per_level || a.wl != b.wl ||
      a.wx != b.wx || a.wy != b.wy || a.trilinear != b.trilinear)
    return false;
  for (size_t j = 0; j < 2; ++j) {
    for (size_t k = 0; k < 4; ++k) {
      const Tap &s = a.taps[j][k], &t = b.taps[j][k];
      if (s.outside != t.outside || s.x != t.x || s.y != t.y || !(s.cell == t.cell)) return false;
    }
  }
  return true;
}

inline std::vector<DetailMapId> maps_of(const std::vector<DetailAccess>& accesses) {
  std::vector<DetailMapId> ids;
  for (const DetailAccess& a : accesses) ids.push_back(a.map);
  return ids;
}

}  // namespace tmu::texram::detail_test
