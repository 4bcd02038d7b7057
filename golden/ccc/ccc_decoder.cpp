#include "ccc/ccc_decoder.hpp"

namespace tmu::ccc {

ImageRgb8 decode_image(const Texture& tex) {
  ImageRgb8 img(static_cast<int>(tex.width), static_cast<int>(tex.height));
  for (uint32_t y = 0; y < tex.height; ++y) {
    for (uint32_t x = 0; x < tex.width; ++x) {
      const uint32_t word = tex.block_word(x / 4, y / 4);
      img.at(static_cast<int>(x), static_cast<int>(y)) =
          tex.clut[texel_index(word, 4 * (y % 4) + x % 4)];
    }
  }
  return img;
}

}  // namespace tmu::ccc
