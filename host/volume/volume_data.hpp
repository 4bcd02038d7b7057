// The voxels of a volume scene: its field generated, or its file read, and for the rgba format
// pre-classified (000 §13: "pre-classified RGBA volumes need only alpha blending"): one 8-bit
// grid per component, the colour opacity-weighted (r a, g a, b a, a; a per voxel of path), so
// that interpolating the components interpolates what each voxel adds to the ray
// (Wittenbrink, Malzbender and Goss 1998) and a transparent voxel's colour cannot bleed.
#pragma once

#include <vector>

#include "volume/volume_scene.hpp"
#include "volume/voxels.hpp"

namespace tmu::host {

// The field's 8-bit values (a raw file as it is; an rgba file's values are not defined:
// throws std::logic_error).
volume::VoxelGrid field_values(const VolumeData& data);

// The grids the unit resamples: raw, one grid; rgba, four (R, G, B, A). Throws InputError naming
// the file when a data file cannot be read.
std::vector<volume::VoxelGrid> volume_grids(const VolumeScene& scene);

// Pre-classification of one voxel value: round(255 (r a, g a, b a, a)).
std::array<uint8_t, 4> preclassify(const TransferFunction& transfer, uint8_t value);

}  // namespace tmu::host
