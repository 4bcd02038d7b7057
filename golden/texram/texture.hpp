// A texture as the TEXRAM holds it: the eight banks of 8-bit cells filled through the layout
// of layout.hpp, and the 256 x RGBA8888 CLUT (index and CCC textures). The golden sampler, the
// hls and rtl memory models all read the same bank image, so the layout is exercised by every
// co-simulation.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "ccc/ccc_texture.hpp"
#include "common/image.hpp"
#include "texram/layout.hpp"
#include "texram/mipmap.hpp"
#include "texram/sampler_config.hpp"
#include "texram/source_texels.hpp"

namespace tmu::texram {

using Clut32 = std::array<uint32_t, 256>;  // RGBA8888
using BankImage = std::array<std::vector<uint8_t>, 8>;

struct TexramTexture {
  TexelKind kind = TexelKind::kLuminance;
  Geometry geometry{0, 0};
  BankImage banks;
  Clut32 clut{};
  SourceTexels source;  // what it was made from: the ideal models read this, not the banks

  uint8_t cell(int level, uint32_t x, uint32_t y, int plane = 0) const {
    const BankCell c = geometry.cell(level, x, y, plane);
    return banks[c.bank][c.address];
  }
};

// Places one pyramid per plane (1 plane, or 4 for true colour) into the banks, every level
// and every replica cell of the small levels. Throws std::invalid_argument when the planes'
// sizes differ or are not powers of two up to 1024.
TexramTexture texture_from_planes(TexelKind kind, const std::vector<Pyramid8>& planes,
                                  const Clut32& clut = {});

// A CCC texture: one ccc::Texture per level (encode_levels), sharing level 0's CLUT; the four
// bytes of each block word go to planes 0..3 (bits 31:24 first) at block resolution.
TexramTexture texture_from_ccc(const std::vector<ccc::Texture>& levels);

// --- Host-side import of an image in each configuration ------------------------------------

// Grey value of a colour: (77 R + 150 G + 29 B + 128) >> 8 (ITU-R BT.601 weights in 8 bits).
constexpr uint8_t luma(Rgb8 c) {
  return static_cast<uint8_t>((77u * c.r + 150u * c.g + 29u * c.b + 128u) >> 8);
}

// One byte plane of an image: pick(pixel) per texel (a colour component, luma).
Level8 plane_of(const ImageRgb8& image, uint8_t (*pick)(Rgb8));

// Builds a texture of `kind` from an image with power-of-two sides up to 1024:
//   luminance  the pyramid of luma(image)
//   single     the pyramid of channel `single_channel` (0 R, 1 G, 2 B; 3 A is 255)
//   rgba       pyramids of R, G, B, and A = 255
//   index      a 256-colour palette (median cut of the level-0 texels), every level's texel the
//              nearest palette entry of the RGB pyramid's texel (mipmaps of indices mean nothing)
//   ccc        the RGB pyramid's levels encoded with one shared CLUT (ccc::encode_levels)
// Throws std::invalid_argument naming the reason.
TexramTexture import_image(const ImageRgb8& image, TexelKind kind, int single_channel = 0);

// A CCC texture from a .ccc file's level 0 (kept as it is); the higher levels are the RGB
// pyramid of its decoded image, encoded against its CLUT. Throws std::invalid_argument.
TexramTexture import_ccc(const ccc::Texture& level0);

// The three RGB pyramids of an image (box filter per channel).
std::array<Pyramid8, 3> rgb_pyramids(const ImageRgb8& image);

}  // namespace tmu::texram
