// One plane of a mipmap level as 8-bit texels, and a pyramid of them: the container the
// mipmap generator (mipmap.hpp) fills and its ideal model (mipmap_ideal.hpp) reads. A
// definition only, no arithmetic, so that the ideal model shares nothing else with golden.
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

}  // namespace tmu::texram
