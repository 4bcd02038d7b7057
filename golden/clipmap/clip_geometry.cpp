#include "clipmap/clip_geometry.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tmu::clipmap {

ClipGeometry::ClipGeometry(int log2_virtual, int log2_tile, int planes)
    : log2_virtual_(log2_virtual), log2_tile_(log2_tile), planes_(planes) {
  if (log2_virtual < kMinLog2Tile || log2_virtual > kMaxLog2Virtual || log2_tile < kMinLog2Tile ||
      log2_tile > kMaxLog2Tile || log2_tile > log2_virtual) {
    throw std::invalid_argument("clip-map of 2^" + std::to_string(log2_virtual) +
                                " texels with tiles of 2^" + std::to_string(log2_tile) +
                                ": the virtual side must be 2^2..2^" +
                                std::to_string(kMaxLog2Virtual) + ", the tile 2^2..2^" +
                                std::to_string(kMaxLog2Tile) + " and no larger");
  }
  if (planes != 1 && planes != formats::kPlanes) {
    throw std::invalid_argument("clip-map: a texel has 1 or 4 byte planes");
  }
  uint32_t used[2] = {0, 0};  // positions so far in the even / odd banks
  for (int l = 0; l < levels(); ++l) {
    offset_[static_cast<size_t>(l)] = used[l & 1];
    used[l & 1] += (stored_side(l) / 2) * (stored_side(l) / 2);
  }
  const uint64_t cells = uint64_t(planes) * std::max(used[0], used[1]);
  if (cells > (uint64_t{1} << formats::kBankAddr.width())) {
    throw std::invalid_argument(
        "clip-map of 2^" + std::to_string(log2_virtual) + " texels with tiles of 2^" +
        std::to_string(log2_tile) + " and " + std::to_string(planes) + " plane(s) needs " +
        std::to_string(cells) + " cells a bank, more than a bank address reaches (" +
        std::to_string(uint64_t{1} << formats::kBankAddr.width()) + ")");
  }
  bank_cells_ = static_cast<uint32_t>(cells);
}

uint32_t ClipGeometry::side(int level) const {
  return uint32_t{1} << std::min(log2_virtual_ - level, log2_tile_);
}

texram::BankCell ClipGeometry::cell(int level, uint32_t x, uint32_t y, int plane) const {
  if (level < 0 || level >= levels() || x >= stored_side(level) || y >= stored_side(level) ||
      plane < 0 || plane >= planes_) {
    throw std::logic_error("ClipGeometry::cell: level " + std::to_string(level) + " (" +
                           std::to_string(x) + ", " + std::to_string(y) + ") plane " +
                           std::to_string(plane) + " is outside");
  }
  const uint32_t position = level_offset(level) + (y >> 1) * (stored_side(level) / 2) + (x >> 1);
  return {texram::bank_of(level, x, y),
          static_cast<uint32_t>(planes_) * position + static_cast<uint32_t>(plane)};
}

}  // namespace tmu::clipmap
