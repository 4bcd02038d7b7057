// Golden model of the CCC decoder of Fig. 5: block word + 4-bit texel address -> decision
// bit -> colour index a or b -> CLUT -> RGB888.
#pragma once

#include <cstdint>

#include "ccc/ccc_texture.hpp"
#include "common/image.hpp"

namespace tmu::ccc {

// Index of the CLUT entry texel `texel` (4*y + x) of `block_word` takes.
constexpr uint8_t texel_index(uint32_t block_word, unsigned texel) {
  const bool take_b = ((block_word >> (texel & 15u)) & 1u) != 0;
  return static_cast<uint8_t>(take_b ? (block_word >> 16) : (block_word >> 24));
}

// Decoded colour of one texel, packed as Rgb888.
inline uint32_t decode_texel(uint32_t block_word, unsigned texel, const Clut& clut) {
  return pack_rgb(clut[texel_index(block_word, texel)]);
}

// Decodes every texel of the texture (golden).
ImageRgb8 decode_image(const Texture& tex);

}  // namespace tmu::ccc
