// Several chips as slabs (000 §13: "the four-chip figures"): the volume cut along one axis into
// N slabs, one a chip, each holding the planes it owns and the ghost planes its resamples read
// beyond them. A resample location belongs to the chip that owns its corner plane i0 (the unit's
// floor of the clamped position, golden/volume/unit.hpp), so each chip computes exactly what the
// single chip would: the same voxels, the same weights, the same one-sided differences on the
// volume's faces (a slab's own faces are never a node's neighbour, see below).
//
// Ghost planes (the unit's reads around i0 along the axis):
//   value mode (rgba): i0 and i1 = i0 + 1: one plane after the slab;
//   raw mode: the value's i0, i1 and the gradient's i0 - 1 and i0 + 2 (the central differences
//   at nodes i0 and i1): one plane before and two after.
// With those, a node's neighbours i - 1 and i + 1 lie in the slab whenever they lie in the
// volume, so the unit takes a one-sided difference only on the volume's own faces.
//
// Owned planes: chip k owns [floor(k n / N), floor((k + 1) n / N)), at least 2 each (a slab of
// one plane and no ghost could not be loaded: VolumeGeometry needs 2).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "volume/marcher.hpp"
#include "volume/unit.hpp"
#include "volume/voxels.hpp"

namespace tmu::host {

struct Slab {
  uint32_t own_begin = 0, own_end = 0;  // the planes this chip owns
  uint32_t begin = 0, end = 0;          // the planes it holds: owned and ghosts
};

struct SlabPlan {
  int axis = 0;         // 0 x, 1 y, 2 z
  uint32_t planes = 0;  // the volume's along the axis
  uint32_t ghost_before = 0, ghost_after = 0;
  std::vector<Slab> slabs;
};

inline constexpr int kMaxChips = 64;

// The ghost planes a mode needs before and after a slab.
std::array<uint32_t, 2> ghost_planes(volume::Mode mode);

// Empty when `chips` slabs along `axis` of a volume of `size` work, else why not (too many
// chips for the planes, a slab too large for a chip's banks).
std::string slab_problem(const std::array<uint32_t, 3>& size, int chips, int axis,
                         volume::Mode mode);

// Throws std::invalid_argument with slab_problem's reason.
SlabPlan plan_slabs(const std::array<uint32_t, 3>& size, int chips, int axis, volume::Mode mode);

// The whole volume as one slab, whatever its size (the ideal's, which has no banks to fit).
SlabPlan whole_volume(const std::array<uint32_t, 3>& size, int axis);

// Chip k's voxels: the planes it holds, renumbered from 0.
volume::VoxelGrid slab_grid(const volume::VoxelGrid& whole, const SlabPlan& plan, size_t chip);

// A run of a ray's locations on one chip.
struct ChipRun {
  size_t chip = 0;
  uint32_t first = 0, count = 0;  // location indices of the whole ray
};

// Locations first .. first + count - 1 of `ray` (whole-volume coordinates) split by the chip
// that owns each: runs in ray order (a ray's planes are monotonic, so each chip has at most one).
std::vector<ChipRun> split_by_chip(const SlabPlan& plan, const volume::Ray& ray, uint32_t first,
                                   uint32_t count);

// Locations first .. first + count - 1 of `ray` as a ray of chip `chip`'s own coordinates: the
// start moved by the locations before `first` and by the planes before the slab (exact integer
// arithmetic, as the marcher's accumulator).
volume::Ray chip_ray(const SlabPlan& plan, size_t chip, const volume::Ray& ray, uint32_t first,
                     uint32_t count);

}  // namespace tmu::host
