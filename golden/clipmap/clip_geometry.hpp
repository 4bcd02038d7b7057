// Where a clip-map lives in the TEXRAM's eight banks (003 §VI, on 000 §2's layout).
//
// A virtual texture of 2^V x 2^V texels has levels 0..V. Its clip-map holds, for each of the
// C = max(V - t, 0) finest levels (the clipped levels), one tile of T = 2^t x 2^t texels, and
// the levels C..V whole (their sides are T and smaller). So level l is stored as a square of
// side min(2^(V-l), T), and a virtual texel (x, y) of a clipped level sits at (x mod T,
// y mod T): toroidal addressing, so that a tile follows the eye by rewriting its rows and
// columns in place, never moving the rest.
//
// The layout is 000 Fig. 2's with those sides: even levels in banks 0-3, odd levels in banks
// 4-7, bank = 4 (l & 1) + (x & 1) + 2 (y & 1); a level's cells row-major over its stored side
// halved; the levels of a parity follow each other from level 0 (or 1) up; a 1 x 1 level is
// stored replicated to 2 x 2; texels of P byte planes interleave (address = P position + p).
// Since T is even, x mod T keeps the parity of x: the 2 x 2 taps of each of two adjacent
// levels still find eight different banks, and a trilinear sample stays one access.
//
// Example: V = 8, t = 5 (256 virtual, 32 x 32 tiles): levels 0..2 clipped (32 x 32 each),
// levels 3..8 whole (32, 16, 8, 4, 2, 1). In banks 0-3 the even levels start at positions 0,
// 256, 512, 576 and 580 (581 positions in all); in banks 4-7 levels 1, 3, 5, 7 at 0, 256, 512
// and 528 (529).
#pragma once

#include <array>
#include <cstdint>

#include "formats/formats.hpp"
#include "texram/layout.hpp"

namespace tmu::clipmap {

inline constexpr int kMaxLog2Virtual = formats::kMaxClipLog2;  // 32k x 32k (003's example)
inline constexpr int kMaxLevels = kMaxLog2Virtual + 1;
inline constexpr int kMinLog2Tile = 2;  // 4 x 4: smaller tiles hold no 2 x 2 footprint to spare
inline constexpr int kMaxLog2Tile = formats::kMaxMipLog2;  // the TEXRAM's largest level: 1024
// Levels that can be clipped: the unit has a region register set for each.
inline constexpr int kMaxClippedLevels = kMaxLog2Virtual - kMinLog2Tile;

class ClipGeometry {
 public:
  // Throws std::invalid_argument for V outside 2..15, t outside 2..10 or t > V, planes other
  // than 1 or 4, or a clip-map whose cells do not fit a bank's addresses (BankAddr).
  ClipGeometry(int log2_virtual, int log2_tile, int planes);

  int log2_virtual() const { return log2_virtual_; }
  int log2_tile() const { return log2_tile_; }
  int levels() const { return log2_virtual_ + 1; }
  int clipped_levels() const { return log2_virtual_ - log2_tile_; }
  int planes() const { return planes_; }
  // The virtual level's side, and the side it is stored at (min(virtual, T)).
  uint32_t virtual_side(int level) const { return uint32_t{1} << (log2_virtual_ - level); }
  uint32_t side(int level) const;
  // The side of the stored square: at least 2 (a 1 x 1 level is replicated).
  uint32_t stored_side(int level) const { return side(level) < 2 ? 2 : side(level); }
  uint32_t level_offset(int level) const { return offset_[static_cast<size_t>(level)]; }
  uint32_t bank_cells() const { return bank_cells_; }

  // The cell of stored position (x, y) (0 .. stored side - 1) of a level, plane `plane`.
  texram::BankCell cell(int level, uint32_t x, uint32_t y, int plane = 0) const;

 private:
  int log2_virtual_, log2_tile_, planes_;
  std::array<uint32_t, kMaxLevels> offset_{};
  uint32_t bank_cells_ = 0;
};

}  // namespace tmu::clipmap
