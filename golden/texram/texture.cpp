#include "texram/texture.hpp"

#include <bit>
#include <stdexcept>

#include "ccc/ccc_decoder.hpp"
#include "ccc/ccc_encoder.hpp"
#include "ccc/median_cut.hpp"

namespace tmu::texram {
namespace {

int log2_side(uint32_t side, const char* what) {
  if (!std::has_single_bit(side) || side > (1u << formats::kMaxMipLog2)) {
    throw std::invalid_argument(std::string("texture ") + what + " " + std::to_string(side) +
                                " is not a power of two up to 1024");
  }
  return std::countr_zero(side);
}

BankImage empty_banks(const Geometry& g) {
  BankImage banks;
  for (auto& b : banks) b.assign(g.bank_cells(), 0);
  return banks;
}

// Writes value to every stored cell that holds grid position (x, y) of `level`.
template <class Value>
void store(const Geometry& g, BankImage& banks, int level, uint32_t x, uint32_t y, int plane,
           Value value) {
  for (uint32_t sy = y; sy < g.stored_height(level); sy += g.grid_height(level)) {
    for (uint32_t sx = x; sx < g.stored_width(level); sx += g.grid_width(level)) {
      const BankCell c = g.cell(level, sx, sy, plane);
      banks[c.bank][c.address] = value;
    }
  }
}

ccc::Vec3 as_vec(uint8_t r, uint8_t g, uint8_t b) {
  return {static_cast<double>(r), static_cast<double>(g), static_cast<double>(b)};
}

Level8 constant_plane(uint32_t w, uint32_t h, uint8_t v) {
  Level8 l(w, h);
  std::fill(l.texels.begin(), l.texels.end(), v);
  return l;
}

ImageRgb8 level_image(const std::array<Pyramid8, 3>& rgb, size_t level) {
  const Level8& r = rgb[0][level];
  ImageRgb8 img(static_cast<int>(r.width), static_cast<int>(r.height));
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    img.pixels[i] = {r.texels[i], rgb[1][level].texels[i], rgb[2][level].texels[i]};
  }
  return img;
}

}  // namespace

Level8 plane_of(const ImageRgb8& image, uint8_t (*pick)(Rgb8)) {
  Level8 l(static_cast<uint32_t>(image.width), static_cast<uint32_t>(image.height));
  for (size_t i = 0; i < image.pixels.size(); ++i) l.texels[i] = pick(image.pixels[i]);
  return l;
}

namespace {

// The texture of `planes` (every level). box_levels: the levels above 0 are the box pyramid of
// level 0 (the imports build them so), and its source keeps level 0 alone.
TexramTexture texture_of_pyramids(TexelKind kind, const std::vector<Pyramid8>& planes,
                                  const Clut32& clut, bool box_levels) {
  if (planes.empty() || planes.front().empty())
    throw std::invalid_argument("texture_from_planes: no planes");
  const Level8& l0 = planes.front().front();
  const Geometry g(log2_side(l0.width, "width"), log2_side(l0.height, "height"),
                   static_cast<int>(planes.size()));
  TexramTexture tex{
      kind, g, empty_banks(g), clut, {kind, l0.width, l0.height, {}, box_levels, false, clut}};
  for (const Pyramid8& plane : planes) {
    tex.source.planes.push_back(box_levels ? Pyramid8{plane.front()} : plane);
  }
  for (size_t p = 0; p < planes.size(); ++p) {
    if (planes[p].size() != static_cast<size_t>(g.levels()) ||
        planes[p].front().width != l0.width || planes[p].front().height != l0.height) {
      throw std::invalid_argument("texture_from_planes: the planes' pyramids differ in size");
    }
    for (int l = 0; l < g.levels(); ++l) {
      const Level8& level = planes[p][static_cast<size_t>(l)];
      for (uint32_t y = 0; y < level.height; ++y) {
        for (uint32_t x = 0; x < level.width; ++x)
          store(g, tex.banks, l, x, y, static_cast<int>(p), level.at(x, y));
      }
    }
  }
  return tex;
}

// A texture whose levels above 0 are the box pyramid of level 0.
TexramTexture texture_of_box_pyramids(TexelKind kind, const std::vector<Pyramid8>& planes) {
  return texture_of_pyramids(kind, planes, {}, true);
}

}  // namespace

TexramTexture texture_from_planes(TexelKind kind, const std::vector<Pyramid8>& planes,
                                  const Clut32& clut) {
  return texture_of_pyramids(kind, planes, clut, false);
}

TexramTexture texture_from_ccc(const std::vector<ccc::Texture>& levels) {
  if (levels.empty()) throw std::invalid_argument("texture_from_ccc: no levels");
  const Geometry g(log2_side(levels[0].width, "width"), log2_side(levels[0].height, "height"),
                   formats::kPlanes,
                   /*block_grid=*/true);
  if (levels.size() != static_cast<size_t>(g.levels()))
    throw std::invalid_argument("texture_from_ccc: level count");
  TexramTexture tex{TexelKind::kCcc, g, empty_banks(g), {}, {}};
  for (size_t i = 0; i < 256; ++i) {
    const Rgb8 c = levels[0].clut[i];
    tex.clut[i] = rgba(c.r, c.g, c.b, 255);
  }
  tex.source = {TexelKind::kCcc, levels[0].width, levels[0].height, {}, false, true, tex.clut};
  tex.source.planes.resize(formats::kPlanes);
  for (int l = 0; l < g.levels(); ++l) {
    const ccc::Texture& t = levels[static_cast<size_t>(l)];
    if (t.width != g.texel_width(l) || t.height != g.texel_height(l) || t.clut != levels[0].clut) {
      throw std::invalid_argument("texture_from_ccc: level " + std::to_string(l) +
                                  " has the wrong size or CLUT");
    }
    for (Pyramid8& plane : tex.source.planes) plane.emplace_back(t.blocks_wide(), t.blocks_high());
    for (uint32_t by = 0; by < t.blocks_high(); ++by) {
      for (uint32_t bx = 0; bx < t.blocks_wide(); ++bx) {
        const uint32_t word = t.block_word(bx, by);
        for (int p = 0; p < formats::kPlanes; ++p) {
          const auto byte = static_cast<uint8_t>(word >> (24 - 8 * p));
          store(g, tex.banks, l, bx, by, p, byte);
          tex.source.planes[static_cast<size_t>(p)].back().at(bx, by) = byte;
        }
      }
    }
  }
  return tex;
}

TexramTexture import_ccc(const ccc::Texture& level0) {
  log2_side(level0.width, "width");
  log2_side(level0.height, "height");
  const auto rgb = rgb_pyramids(ccc::decode_image(level0));
  std::vector<ccc::Texture> levels{level0};
  for (size_t l = 1; l < rgb[0].size(); ++l)
    levels.push_back(ccc::encode_with_clut(level_image(rgb, l), level0.clut));
  return texture_from_ccc(levels);
}

std::array<Pyramid8, 3> rgb_pyramids(const ImageRgb8& image) {
  return {build_pyramid(plane_of(image, [](Rgb8 c) { return c.r; })),
          build_pyramid(plane_of(image, [](Rgb8 c) { return c.g; })),
          build_pyramid(plane_of(image, [](Rgb8 c) { return c.b; }))};
}

TexramTexture import_image(const ImageRgb8& image, TexelKind kind, int single_channel) {
  const auto w = static_cast<uint32_t>(image.width), h = static_cast<uint32_t>(image.height);
  log2_side(w, "width");
  log2_side(h, "height");
  switch (kind) {
    case TexelKind::kLuminance:
      return texture_of_box_pyramids(kind, {build_pyramid(plane_of(image, luma))});
    case TexelKind::kSingle: {
      if (single_channel < 0 || single_channel > 3)
        throw std::invalid_argument("single channel must be 0..3");
      if (single_channel == 3)
        return texture_of_box_pyramids(kind, {build_pyramid(constant_plane(w, h, 255))});
      return texture_of_box_pyramids(kind,
                                     {rgb_pyramids(image)[static_cast<size_t>(single_channel)]});
    }
    case TexelKind::kTrueColour: {
      auto rgb = rgb_pyramids(image);
      return texture_of_box_pyramids(
          kind, {rgb[0], rgb[1], rgb[2], build_pyramid(constant_plane(w, h, 255))});
    }
    case TexelKind::kIndex: {
      std::vector<ccc::WeightedColour> colours;
      for (const Rgb8& c : image.pixels) colours.push_back({as_vec(c.r, c.g, c.b), 1});
      const ccc::Palette palette = ccc::median_cut(colours);
      const ccc::PaletteSearch search(palette);
      const auto rgb = rgb_pyramids(image);
      Pyramid8 indices;
      for (size_t l = 0; l < rgb[0].size(); ++l) {
        Level8 level(rgb[0][l].width, rgb[0][l].height);
        for (size_t i = 0; i < level.texels.size(); ++i) {
          level.texels[i] =
              search.nearest(as_vec(rgb[0][l].texels[i], rgb[1][l].texels[i], rgb[2][l].texels[i]));
        }
        indices.push_back(std::move(level));
      }
      Clut32 clut{};
      for (size_t i = 0; i < 256; ++i)
        clut[i] = rgba(palette.clut[i].r, palette.clut[i].g, palette.clut[i].b, 255);
      return texture_from_planes(kind, {indices}, clut);
    }
    case TexelKind::kCcc: {
      const auto rgb = rgb_pyramids(image);
      std::vector<ImageRgb8> levels;
      for (size_t l = 0; l < rgb[0].size(); ++l) levels.push_back(level_image(rgb, l));
      return texture_from_ccc(ccc::encode_levels(levels));
    }
  }
  throw std::invalid_argument("unknown texel kind");
}

}  // namespace tmu::texram
