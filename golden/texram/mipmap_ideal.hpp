// The ideal mipmap (000 §12): every level the exact 2^l x 2^l box mean of level 0, in double
// precision, computed from level 0 by its own code (no golden arithmetic: the truth the
// generator's rounding rule, texram/mipmap.hpp, is measured against). It shares with golden
// only the definition of a level's container, texram/level8.hpp.
#pragma once

#include <vector>

#include "texram/level8.hpp"

namespace tmu::texram {

struct LevelD {
  uint32_t width = 0, height = 0;
  std::vector<double> texels;  // row-major
  double at(uint32_t x, uint32_t y) const { return texels[size_t{y} * width + x]; }
};

// Level l texel (x, y): the mean of the level-0 texels [x 2^l, (x + 1) 2^l) x [y 2^l, ...), a
// side shorter than 2^l taken whole (the box of a one-texel-wide level repeats its column,
// which leaves the mean unchanged). Level 0 first, down to 1 x 1; sides powers of two.
std::vector<LevelD> ideal_pyramid(const Level8& level0);

// Per level l >= 1, the mean signed error (pyramid - ideal) and the largest absolute one, in
// 8-bit levels.
struct LevelError {
  double mean = 0, max_abs = 0;
};
std::vector<LevelError> pyramid_error(const Pyramid8& pyramid, const std::vector<LevelD>& ideal);

}  // namespace tmu::texram
