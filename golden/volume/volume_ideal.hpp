// The ideal volume unit (double precision) from the source voxels, by its own code (no golden
// arithmetic): the exact location start + n step of the real ray, trilinear interpolation at
// the exact position, central-difference gradients at the voxels (one-sided on the volume's
// faces: the definition of unit.hpp) interpolated trilinearly. Positions are clamped to the
// volume per axis, as the unit does.
#pragma once

#include <array>

#include "volume/voxels.hpp"

namespace tmu::volume {

using Point = std::array<double, 3>;  // voxels

struct IdealResample {
  double value = 0;  // voxel values
  Point gradient{};  // voxel values per voxel
};

IdealResample ideal_resample(const VoxelGrid& grid, const Point& p);

// Location n of a real ray: start + n step.
Point ideal_location(const Point& start, const Point& step, double n);

// The gradient of the grid at voxel (x, y, z), component `axis` (the central difference / 2).
double ideal_node_gradient(const VoxelGrid& grid, long x, long y, long z, int axis);

}  // namespace tmu::volume
