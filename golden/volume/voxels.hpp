// A volume data set as the host holds it: X x Y x Z 8-bit voxels, x fastest. Voxel (x, y, z)
// stands for the point (x, y, z) of the volume's coordinates (voxel centres at integers).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace tmu::volume {

struct VoxelGrid {
  uint32_t nx = 0, ny = 0, nz = 0;
  std::vector<uint8_t> voxels;  // nx * ny * nz, index x + nx (y + ny z)

  VoxelGrid() = default;
  VoxelGrid(uint32_t x, uint32_t y, uint32_t z)
      : nx(x), ny(y), nz(z), voxels(size_t{x} * y * z, 0) {}
  size_t index(uint32_t x, uint32_t y, uint32_t z) const {
    if (x >= nx || y >= ny || z >= nz) throw std::out_of_range("VoxelGrid: voxel outside");
    return x + size_t{nx} * (y + size_t{ny} * z);
  }
  uint8_t at(uint32_t x, uint32_t y, uint32_t z) const { return voxels[index(x, y, z)]; }
  uint8_t& at(uint32_t x, uint32_t y, uint32_t z) { return voxels[index(x, y, z)]; }
};

}  // namespace tmu::volume
