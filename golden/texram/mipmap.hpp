// Mipmap generation (000 §12, Fig. 14): the 2 x 2 box filter, level by level down to 1 x 1,
// on one plane of 8-bit values (a luminance texture, one component of a true-colour one).
//
// Rounding rule, stated once: a level-(l+1) value is (a + b + c + d + 2) >> 2 of its four
// level-l values, the sum exact and rounded half up (the adders 1402 and 1410 keep every bit;
// the two dropped bits are rounded at the end). When level l is one texel wide (or high), the
// 2 x 2 window repeats that column (row): the value is (2a + 2b + 2) >> 2 = (a + b + 1) >> 1.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tmu::texram {

struct Level8 {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> texels;  // row-major

  Level8() = default;
  Level8(uint32_t w, uint32_t h) : width(w), height(h), texels(size_t{w} * h) {}
  uint8_t& at(uint32_t x, uint32_t y) { return texels[size_t{y} * width + x]; }
  uint8_t at(uint32_t x, uint32_t y) const { return texels[size_t{y} * width + x]; }
  friend bool operator==(const Level8&, const Level8&) = default;
};

using Pyramid8 = std::vector<Level8>;  // level 0 first, the 1 x 1 level last

// The box filter of four values, rounded half up.
constexpr uint8_t box4(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return static_cast<uint8_t>((a + b + c + d + 2) >> 2);
}

// Every level of a power-of-two level 0 (sides 1..1024; throws std::invalid_argument).
Pyramid8 build_pyramid(const Level8& level0);

}  // namespace tmu::texram
