// Solid-texture coordinates as stimulus, shared by the blocks that take them (noise, fractal,
// material's sample channel): an item of (u, v, w) SolidCoord SQ12.12, the directed hard
// cases of the lattice, the random mixes, and the coverage cases of the coordinates alone.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "harness/block.hpp"
#include "harness/txn.hpp"
#include "perlin/noise.hpp"

namespace tmu::tb::solid {

inline constexpr int kCoordW = 24;                             // SolidCoord's width
inline constexpr int32_t kUnit = 1 << perlin::kCoordFracBits;  // 1.0, raw SQ12.12
inline constexpr int32_t kCoordMin = -(1 << (kCoordW - 1));
inline constexpr int32_t kCoordMax = (1 << (kCoordW - 1)) - 1;

bool in_range(int64_t x);
// x as a 24-bit two's complement value (the coordinate an octave shift wraps to).
int32_t wrap24(int64_t x);

// An item of raw SQ12.12 coordinates in slots first, first + 1, first + 2 (each -2^23 ..
// 2^23 - 1), and the coordinates of such an item, sign-extended.
Txn item(int32_t u, int32_t v, int32_t w, int first = 0);
std::array<int32_t, 3> coords(const Txn& item, int first = 0);
// Appends item(u, v, w) when all three are SolidCoord values.
void add(std::vector<Txn>& items, int64_t u, int64_t v, int64_t w);

// The lattice value (golden's hash) at integer lattice coordinates, each taken mod 4096.
int32_t lattice_value_at(int32_t i, int32_t j, int32_t k);
using Lattice = std::array<int32_t, 3>;
// The first n lattice points of the cube [-16, 16)^3 that satisfy `want` (in a fixed order).
std::vector<Lattice> lattice_points_where(const std::function<bool(const Lattice&)>& want,
                                          size_t n);

// Directed coordinates: lattice points (among them ones whose lattice value is -1.0 and
// +127/128), cell boundaries (raw fractions ..FFF, ..000, ..001, the fade index's edges),
// every fade index on every axis, negative coordinates, the SolidCoord extremes, coordinates
// whose octave shifts leave 24 bits, u = v = w.
std::vector<Txn> directed_items();
// Random coordinates: uniform, near the origin, lattice points, cell boundaries, u = v = w,
// large (octave overflow), mixed per axis.
std::vector<Txn> random_items(std::mt19937_64& rng, size_t count);

// The coverage cases of the coordinates alone, and their counting.
std::vector<std::string> coord_cases();
void cover_coords(const std::array<int32_t, 3>& c, Coverage& cov);

}  // namespace tmu::tb::solid
