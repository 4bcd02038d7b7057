#include "volume/layout.hpp"

#include <stdexcept>
#include <string>

#include "formats/constants.hpp"
#include "formats/formats.hpp"
#include "texram/page_model.hpp"

namespace tmu::volume {

static_assert(formats::kVolumeBrickCells == 8 * 4 * 16 &&
              formats::kVolumeBrickCells == 1 << texram::kPageBits);

VolumeGeometry::VolumeGeometry(uint32_t nx, uint32_t ny, uint32_t nz) : nx_(nx), ny_(ny), nz_(nz) {
  for (uint32_t n : {nx, ny, nz}) {
    if (n < 2 || n > 512) {
      throw std::invalid_argument("VolumeGeometry: a side of " + std::to_string(n) +
                                  " voxels (2..512)");
    }
  }
  bricks_x_ = (nx + 15) / 16;
  bricks_y_ = (ny + 7) / 8;
  const uint64_t cells =
      uint64_t{bricks_x_} * bricks_y_ * ((nz + 15) / 16) * formats::kVolumeBrickCells;
  if (cells > (uint64_t{1} << formats::kBankAddr.width())) {
    throw std::invalid_argument("VolumeGeometry: " + std::to_string(nx) + " x " +
                                std::to_string(ny) + " x " + std::to_string(nz) +
                                " needs more than 2^21 cells a bank");
  }
  bank_cells_ = static_cast<uint32_t>(cells);
}

texram::BankCell VolumeGeometry::cell(uint32_t x, uint32_t y, uint32_t z) const {
  if (x >= nx_ || y >= ny_ || z >= nz_) throw std::out_of_range("VolumeGeometry: voxel outside");
  const uint32_t brick = (x >> 4) + bricks_x_ * ((y >> 3) + bricks_y_ * (z >> 4));
  return {voxel_bank(x, y), 512 * brick + 32 * (z & 15) + 8 * ((y >> 1) & 3) + ((x >> 1) & 7)};
}

}  // namespace tmu::volume
