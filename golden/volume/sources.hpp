// Volume sources for tests and scenes: 8-bit voxel arrays of analytic fields.
//
// Marschner-Lobb (Marschner and Lobb 1994, the standard reconstruction test):
//   f(x, y, z) = (1 - sin(pi z / 2) + alpha (1 + rho_r(sqrt(x^2 + y^2)))) / (2 (1 + alpha)),
//   rho_r(r) = cos(2 pi f_M cos(pi r / 2)), f_M = 6, alpha = 0.25, on [-1, 1]^3, f in [0, 1];
//   voxel (i, j, k) of an n^3 grid samples the point -1 + 2 (i, j, k) / (n - 1), stored as
//   round(255 f) (half up).
// Sphere distance field: voxel = clamp(round(128 + slope (R - |p - c|)), 0, 255), c the
//   volume's centre ((n - 1) / 2 per axis), R and the distance in voxels, slope in voxel values
//   per voxel: 128 on the surface, larger inside. Its gradient points to the centre: the
//   surface's outward normal is -gradient / |gradient|.
#pragma once

#include <array>
#include <cstdint>

#include "volume/voxels.hpp"

namespace tmu::volume {

// The test signal's two parameters: the ripples' frequency f_M and their amplitude alpha.
struct MarschnerLobb {
  double f_m = 6.0, alpha = 0.25;
};
double marschner_lobb(double x, double y, double z, const MarschnerLobb& p = {});  // f in [0, 1]
VoxelGrid marschner_lobb_grid(uint32_t n);
// Any grid size: voxel (i, j, k) samples -1 + 2 (i, j, k) / (n - 1) per axis, each axis over
// [-1, 1] (a stretched field where the sizes differ).
VoxelGrid marschner_lobb_grid(uint32_t nx, uint32_t ny, uint32_t nz,
                             const MarschnerLobb& p = {});

VoxelGrid sphere_grid(uint32_t nx, uint32_t ny, uint32_t nz, double radius, double slope);
// The sphere's centre in voxel coordinates for that grid.
std::array<double, 3> sphere_centre(const VoxelGrid& grid);

}  // namespace tmu::volume
