// The voxel layout over the TEXRAM's four level-0 banks (000 §13: "only the four larger memory
// arrays holding level 0 are used"; "the special address interleaving scheme assures that each
// access is non-conflicting"). 8-bit voxels, one per cell.
//
// - Bank of voxel (x, y, z): (x & 1) + 2 (y & 1), level 0's rule of the 2-D layout
//   (docs/texram.md) applied to every slice. Each of the unit's accesses reads voxels of one
//   slice z whose x take two values of different parity (x0, x0 + 1 or x0 - 1, x0 + 2) and
//   whose y do too (y0, y0 + 1 or y0 - 1, y0 + 2): four different banks (docs/volume.md, the
//   access order in unit.hpp; proved exhaustively by VolumeLayoutTest).
// - Address within the bank: the volume is cut into bricks of 16 x 8 x 16 voxels, which are
//   8 x 4 x 16 = 512 cells in each bank, one DRAM page (page_model.hpp: 2^9 cells): the cells
//   of a brick form one page, the bricks follow each other x fastest, then y, then z.
//   address = 512 brick + 32 (z & 15) + 8 ((y >> 1) & 3) + ((x >> 1) & 7),
//   brick = bx + BX (by + BY bz), bx = x >> 4, by = y >> 3, bz = z >> 4, BX = ceil(X / 16),
//   BY = ceil(Y / 8). A resample's eight corners and their gradient neighbours then share a
//   page in each bank except where the neighbourhood crosses a brick's face. The shape was
//   chosen among five of 512 cells by the page faults of the ray sets of docs/volume.md (8 x 8
//   x 8 cells: 67 / 308 ms for the value / raw z-rays, 8 x 4 x 16: 65 / 298, 2 x 2 x 128:
//   63 / 326 but 78 / 341 along x).
// - Any size X, Y, Z of 2..512 voxels (VolumeSize; a central difference needs two voxels per
//   axis) whose padded bricks fit the 21-bit bank address (BankAddr): 2^21 cells a bank,
//   8 M voxels, e.g. 256 x 256 x 128. The padding cells are never read.
#pragma once

#include <cstdint>

#include "texram/layout.hpp"

namespace tmu::volume {

inline constexpr unsigned kVolumeBanks = 4;  // the level-0 banks 0..3

class VolumeGeometry {
 public:
  // Throws std::invalid_argument for a size outside 2..512 or too large for the banks.
  VolumeGeometry(uint32_t nx, uint32_t ny, uint32_t nz);
  uint32_t nx() const { return nx_; }
  uint32_t ny() const { return ny_; }
  uint32_t nz() const { return nz_; }
  uint32_t bank_cells() const { return bank_cells_; }  // cells used in each bank
  // The bank (0..3) and the address of voxel (x, y, z) (inside the volume).
  texram::BankCell cell(uint32_t x, uint32_t y, uint32_t z) const;

 private:
  uint32_t nx_, ny_, nz_, bricks_x_, bricks_y_, bank_cells_;
};

constexpr unsigned voxel_bank(uint32_t x, uint32_t y) { return (x & 1u) + 2u * (y & 1u); }

}  // namespace tmu::volume
