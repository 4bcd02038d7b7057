// The offline CCC encoder (000 §3): every 4x4 block is reduced to two colours a, b and 16
// decision bits, then all block colours are quantized together to the 256-entry CLUT, and
// each block's two CLUT indices and 16 bits are chosen against that CLUT to minimise the
// block's squared error over the texels inside the image (docs/ccc.md).
// Host code; compression is done in advance, so it favours quality over speed.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "ccc/ccc_texture.hpp"
#include "ccc/symmetric_eigen.hpp"
#include "common/image.hpp"

namespace tmu::ccc {

// Texels of block (bx, by), texel index 4*y + x. Texels beyond the image repeat the last
// column / row (the container's edge padding).
std::array<Rgb8, 16> block_texels(const ImageRgb8& image, uint32_t bx, uint32_t by);

struct TwoColourBlock {
  Vec3 a{};           // mean of the texels whose decision bit is 0
  Vec3 b{};           // mean of the texels whose decision bit is 1; equals a if there are none
  uint16_t bits = 0;  // bit 4*y + x set: the texel takes b
};

// Splits a block into two clusters by the plane through the texels' mean colour
// perpendicular to the axis of minimum moment of inertia (eq. 1). Texels strictly beyond
// the plane (projection > mean projection + a tolerance) take b, all others a, so
// projections equal up to rounding never split. Deterministic and invariant under
// permutation of the texels.
TwoColourBlock cluster_block(const std::array<Rgb8, 16>& texels);

// Encodes an image (width, height >= 1; throws std::invalid_argument otherwise).
// Deterministic: the same image always gives the same bytes.
Texture encode(const ImageRgb8& image);

// Encodes several images (e.g. the levels of a mipmap) with one shared CLUT, quantized from
// the cluster colours of all of them: the hardware has a single CLUT per texture.
std::vector<Texture> encode_levels(const std::vector<ImageRgb8>& images);

// Encodes an image against a given CLUT (e.g. the higher levels of a mipmap whose level 0
// came in a .ccc file): every entry may be chosen.
Texture encode_with_clut(const ImageRgb8& image, const Clut& clut);

// The unquantized two-colour reconstruction: every texel takes its cluster mean rounded to
// the nearest 8-bit value. What encode() would give with an unlimited CLUT.
ImageRgb8 two_colour_ideal(const ImageRgb8& image);

struct EncodeReport {
  double psnr_ideal = 0.0;      // two_colour_ideal(input) against the input, dB
  double psnr_encoded = 0.0;    // decode_image(encoded) against the input, dB
  double bits_per_texel = 0.0;  // container bytes * 8 / (width * height), header included
};

EncodeReport report_encoding(const ImageRgb8& input, const Texture& encoded);
EncodeReport report_encoding(const ImageRgb8& input);  // encodes `input` itself

}  // namespace tmu::ccc
