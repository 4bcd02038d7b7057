// A real-looking data set: a CT-like scan of an engine part (the kind of object industrial CT
// scans: two cylinders of a cast aluminium block with cooling fins, steel cylinder liners,
// aluminium pistons, a steel crankshaft running through a crankcase cavity and out of the
// block, four steel bolts), made as a scanner would see it: each voxel the mean of 2 x 2 x 2
// points inside it (the partial volume effect), blurred by a Gaussian of 0.8 voxel (the point
// spread) and with Gaussian noise of 3 voxel values, stored as 8-bit voxels: air 20, aluminium
// 110, steel 220 (where a part is thick enough to keep its level through the blur).
// `texsim volume-gen engine` writes it as a raw file; a volume scene's {"field": "engine"} makes
// the same voxels in memory.
//
// Axes: x along the crankshaft, y across, z up; the part fills [-1, 1] on each axis (a volume
// with different sides is a stretched part).
#pragma once

#include <cstdint>

#include "volume/voxels.hpp"

namespace tmu::host {

volume::VoxelGrid engine_scan(uint32_t nx, uint32_t ny, uint32_t nz, uint32_t seed);

// The part's density at a point of [-1, 1]^3: 0 air, 0.45 aluminium, 1 steel.
double engine_density(double x, double y, double z);

}  // namespace tmu::host
