#include "texram/layout.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tmu::texram {

Geometry::Geometry(int log2_w, int log2_h, int planes, bool block_grid)
    : log2_w_(log2_w), log2_h_(log2_h), planes_(planes), block_grid_(block_grid) {
  if (planes != 1 && planes != formats::kPlanes) {
    throw std::invalid_argument("texram::Geometry: a texture has 1 or 4 planes");
  }
  if (log2_w < 0 || log2_h < 0 || log2_w > formats::kMaxMipLog2 || log2_h > formats::kMaxMipLog2) {
    throw std::invalid_argument("texram::Geometry: log2 sizes must be 0.." +
                                std::to_string(formats::kMaxMipLog2));
  }
  levels_ = std::max(log2_w, log2_h) + 1;
  uint32_t used[2] = {0, 0};  // cells used so far in the even / odd banks
  for (int l = 0; l < levels_; ++l) {
    const uint32_t w = texel_width(l), h = texel_height(l);
    grid_w_[static_cast<size_t>(l)] = block_grid ? (w + 3) / 4 : w;
    grid_h_[static_cast<size_t>(l)] = block_grid ? (h + 3) / 4 : h;
    offset_[static_cast<size_t>(l)] = used[l & 1];
    used[l & 1] += (stored_width(l) / 2) * (stored_height(l) / 2);
  }
  bank_cells_ = static_cast<uint32_t>(planes) * std::max(used[0], used[1]);
}

uint32_t Geometry::texel_width(int level) const {
  return uint32_t{1} << std::max(log2_w_ - level, 0);
}
uint32_t Geometry::texel_height(int level) const {
  return uint32_t{1} << std::max(log2_h_ - level, 0);
}
uint32_t Geometry::stored_width(int level) const { return std::max(grid_width(level), 2u); }
uint32_t Geometry::stored_height(int level) const { return std::max(grid_height(level), 2u); }

BankCell Geometry::cell(int level, uint32_t x, uint32_t y, int plane) const {
  if (level < 0 || level >= levels_ || x >= stored_width(level) || y >= stored_height(level) ||
      plane < 0 || plane >= planes_) {
    throw std::logic_error("texram::Geometry::cell: level " + std::to_string(level) + " (" +
                           std::to_string(x) + ", " + std::to_string(y) + ") plane " +
                           std::to_string(plane) + " is outside the texture");
  }
  const uint32_t position = level_offset(level) + (y >> 1) * (stored_width(level) / 2) + (x >> 1);
  return {bank_of(level, x, y),
          static_cast<uint32_t>(planes_) * position + static_cast<uint32_t>(plane)};
}

}  // namespace tmu::texram
