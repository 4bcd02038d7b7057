// The ray sets of the figures (docs/volume.md, "Figures"): one resample per voxel over an
// X x Y x Z volume, rays one after another, i fastest. What the golden figures and the
// co-simulated hardware's cycle counts (`texsim cosim volume --volume-rays SET`) both run.
//   z        along +z from (i + 1/2, j + 1/2, 1/2), X Y rays of Z resamples
//   x        along +x from (1/2, j + 1/2, k + 1/2), Y Z rays of X resamples
//   oblique  from (i + 1/2, j + 1/2, 1/2) with step (1/8, 1/16, 1), X Y rays of Z resamples
//            (leaving the side faces: clamped)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volume/marcher.hpp"

namespace tmu::volume {

// Throws std::invalid_argument naming the sets for another name.
std::vector<Ray> figure_rays(const std::string& set, uint32_t nx, uint32_t ny, uint32_t nz);

}  // namespace tmu::volume
