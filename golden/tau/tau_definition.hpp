// What the tau unit's golden model (tau_unit.hpp) and its ideal (tau_ideal.hpp) share: the
// grid's shape and the interpolation's name, and the extrapolation rule below. Definitions
// only, no arithmetic (tests/ideal_independence_test.sh; docs/tau.md lists this file).
//
// The node grid: cells_s x cells_t cells, 1..kMaxCells each, (cells_s + 1) (cells_t + 1) nodes
// (u, v); the unit's memory holds node (i, j) at address i + kStride j, so the address of a
// node does not depend on the configuration (a grid can be rewritten for another size node by
// node, and kStride = kMaxCells + 1 is the widest row).
//
// Extrapolation (the spline's stencil reaches one node beyond the grid on either side):
//   n(-1, j)        = 2 n(0, j) - n(1, j)
//   n(cells_s+1, j) = 2 n(cells_s, j) - n(cells_s - 1, j)
// and the same along t; a corner is extrapolated along both (the order does not matter:
// bilinear extrapolation). With one cell, cells - 1 = 0. So the spline reproduces an affine
// map sampled into the grid exactly, up to the last cell's edge.
#pragma once

#include <cstdint>

namespace tmu::tau {

// Claim 5 (linear: bilinear in each cell) or claim 6 (a spline: Catmull-Rom in s and in t).
enum class Interp : uint8_t { kLinear = 0, kSpline = 1 };

inline constexpr int kMaxCells = 16;
inline constexpr int kStride = kMaxCells + 1;     // 17: nodes of the widest row
inline constexpr int kNodes = kStride * kStride;  // 289 addresses, 0 .. 288

}  // namespace tmu::tau
