// The TEXRAM's mipmap memory (000 §2, Fig. 2): eight banks of 8-bit cells, even levels in
// banks 0-3 and odd levels in banks 4-7, bank = 4 (level & 1) + (x & 1) + 2 (y & 1) within a
// level, so the 2 x 2 texels of each of two adjacent levels, the eight texels of a trilinear
// sample, sit in eight different banks and come out in one access. Addresses are computed
// locally from the level and the coordinates.
//
// Choices where the text is silent:
// - A level narrower than 2 texels (or CCC blocks) in a direction is stored replicated to 2
//   in that direction (cell (x, y) holds texel (x mod w, y mod h)), so a footprint in it still
//   finds its four taps in four banks; the 1 x 1 top level takes four cells.
// - Within a bank, the levels of its parity follow each other from level 0 (or 1) upward; a
//   level's cells are row-major over its stored size halved in both directions.
// - A texture has one byte plane (luminance, index, single component) or four (true colour
//   R, G, B, A; the four bytes of a CCC block word, 31:24 first). The planes of a texel are
//   interleaved cell by cell (address = planes * position + plane), so the four accesses of a
//   true-colour sample stay in one DRAM page, as the patent's "2 x 2 texel space assigned one
//   RGBa quadruple" does.
// - A grid is texels, or for CCC textures 4 x 4 blocks: level l of a 2^a x 2^b texture is
//   max(2^(a-l), 1) texels wide, and ceil of that / 4 blocks.
#pragma once

#include <array>
#include <cstdint>

#include "formats/formats.hpp"

namespace tmu::texram {

inline constexpr int kMaxLevels = formats::kMaxMipLog2 + 1;

struct BankCell {
  unsigned bank = 0;     // 0..7
  uint32_t address = 0;  // cell within the bank
  friend bool operator==(const BankCell&, const BankCell&) = default;
};

class Geometry {
 public:
  // A 2^log2_w x 2^log2_h texture (each 0..MaxMipLog2) of `planes` (1 or 4) byte planes;
  // block_grid: the grid is CCC blocks.
  Geometry(int log2_w, int log2_h, int planes = 1, bool block_grid = false);

  int levels() const { return levels_; }  // level 0 .. levels() - 1 (the 1 x 1 texel level last)
  uint32_t texel_width(int level) const;  // texels
  uint32_t texel_height(int level) const;
  uint32_t grid_width(int level) const {
    return grid_w_[static_cast<size_t>(level)];
  }  // grid cells
  uint32_t grid_height(int level) const { return grid_h_[static_cast<size_t>(level)]; }
  uint32_t stored_width(int level) const;   // max(grid width, 2)
  uint32_t stored_height(int level) const;  // max(grid height, 2)
  // First position of `level` in its banks (a position holds `planes` cells).
  uint32_t level_offset(int level) const { return offset_[static_cast<size_t>(level)]; }
  uint32_t bank_cells() const { return bank_cells_; }  // cells used in the fuller bank
  int planes() const { return planes_; }
  bool block_grid() const { return block_grid_; }
  int log2_width() const { return log2_w_; }
  int log2_height() const { return log2_h_; }

  // The cell of grid position (x, y) of `level`, plane `plane`. x and y are stored
  // coordinates: 0 .. stored size - 1 (a grid coordinate, or its replica).
  BankCell cell(int level, uint32_t x, uint32_t y, int plane = 0) const;

 private:
  int log2_w_, log2_h_, planes_;
  bool block_grid_;
  int levels_;
  std::array<uint32_t, kMaxLevels> grid_w_{}, grid_h_{}, offset_{};  // offset in positions
  uint32_t bank_cells_ = 0;
};

// The bank of a stored position: 4 (level & 1) + (x & 1) + 2 (y & 1).
constexpr unsigned bank_of(int level, uint32_t x, uint32_t y) {
  return 4u * (static_cast<unsigned>(level) & 1u) + (x & 1u) + 2u * (y & 1u);
}

}  // namespace tmu::texram
