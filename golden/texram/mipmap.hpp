// Mipmap generation (000 §12, Fig. 14): the 2 x 2 box filter, level by level down to 1 x 1,
// on one plane of 8-bit values (a luminance texture, one component of a true-colour one).
//
// Rounding rule, stated once (000 §12 leaves it open; docs/texram.md, "The pyramid's rounding",
// has the sweep that chose it). Besides its 8-bit texels every level keeps their carried values:
// the box means with k_l = min(2 l, carry) fraction bits (level 0: its texels, k_0 = 0). The box
// sum S of a level-(l+1) texel is the exact sum of the four level-l carried values below it; its
// 8-bit texel is S / 2^(k_l + 2) rounded half up, once; its carried value is S rounded half up to
// k_(l+1) fraction bits. With the default carry, kExactCarry, nothing is ever dropped: S is the
// exact sum of the level-0 texels the texel covers, and every level is within 0.5 of the exact
// box mean of level 0. carry = 0 rounds every level, (a + b + c + d + 2) >> 2 of the rounded
// texels below, and drifts by about +0.11 of a level per level. When level l is one texel wide
// (or high), the 2 x 2 window repeats that column (row): its pair is twice the texel.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "formats/formats.hpp"
#include "texram/level8.hpp"

namespace tmu::texram {

// The carry that keeps every box sum exact: level l's sums have 2 l fraction bits.
inline constexpr int kExactCarry = 2 * formats::kMaxMipLog2;

// The fraction bits of level l's carried values.
constexpr int carried_bits(int level, int carry) { return std::min(2 * level, carry); }

// The 8-bit texel of a box sum of four values with k fraction bits: rounded half up, once.
constexpr uint8_t box_texel(uint32_t sum, int k) {
  return static_cast<uint8_t>((sum + (uint32_t{2} << k)) >> (k + 2));
}

// The carried value, with k_next (k .. k + 2) fraction bits, of a box sum of four values with
// k fraction bits: rounded half up.
constexpr uint32_t box_carry(uint32_t sum, int k, int k_next) {
  const int drop = k + 2 - k_next;
  return drop == 0 ? sum : (sum + (uint32_t{1} << (drop - 1))) >> drop;
}

// Every level of a power-of-two level 0 (sides 1..1024; throws std::invalid_argument), under the
// rounding rule of `carry` (0 .. kExactCarry).
Pyramid8 build_pyramid(const Level8& level0, int carry = kExactCarry);

}  // namespace tmu::texram
