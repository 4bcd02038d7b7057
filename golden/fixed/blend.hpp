// The one blend rule of the project: filter weights are UQ0.8 fractions f (0..255), the
// pair of weights applied to two samples is (256 - f, f), products are kept exact and the
// sum of all weighted samples is rounded once, half up, back to the sample format.
// Bilinear: 2 x 2 weights -> one rounding of a 16-fraction-bit sum. The trilinear unit
// extends the same rule with a third weight and one rounding of a 24-fraction-bit sum.
#pragma once

#include <array>
#include <cstdint>

#include "fixed/fixed.hpp"

namespace tmu::fx {

inline constexpr int kWeightOne = 256;  // the weight pair (256 - f, f) sums to this

// Bilinear blend of one 8-bit channel. c00 at (x0, y0), c10 at (x1, y0), c01 at (x0, y1),
// c11 at (x1, y1); fx, fy in 0..255. Result 0..255, exact except for the final rounding.
constexpr uint32_t bilerp_u8(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, uint32_t fx,
                             uint32_t fy) {
  const int64_t top = int64_t{c00} * (kWeightOne - fx) + int64_t{c10} * fx;  // UQ8.8
  const int64_t bot = int64_t{c01} * (kWeightOne - fx) + int64_t{c11} * fx;  // UQ8.8
  const int64_t sum = top * (kWeightOne - fy) + bot * fy;                    // UQ8.16
  return static_cast<uint32_t>(shift_right_round(sum, 16, Round::kHalfUp));
}

// The same rule at W weight bits (1..8) over eight samples of any signed integer format:
// c[x + 2 y + 4 z] at the corners of a cell, weights wx, wy, wz in 0 .. 2^W - 1 (of the
// corner x1, y1, z1), the pairs (2^W - w, w); the exact sum of the products dropped by
// 3W - keep bits (keep: fraction bits the result keeps beyond the samples', 0..3W), rounded
// once, half up (toward +infinity on a tie, negative sums too). The volume unit blends voxel
// values (8-bit, keep 0) and central differences (1 fraction bit, keep 3: SQ9.4) through it.
constexpr int64_t trilerp(const std::array<int64_t, 8>& c, uint32_t wx, uint32_t wy, uint32_t wz,
                          int weight_bits, int keep = 0) {
  const int64_t one = int64_t{1} << weight_bits;
  const int64_t ws[3][2] = {{one - wx, wx}, {one - wy, wy}, {one - wz, wz}};
  int64_t sum = 0;
  for (size_t i = 0; i < 8; ++i) sum += c[i] * ws[0][i & 1] * ws[1][(i >> 1) & 1] * ws[2][i >> 2];
  return shift_right_round(sum, 3 * weight_bits - keep, Round::kHalfUp);
}

}  // namespace tmu::fx
