// The ideal volume engine: golden/volume/volume_ideal (double precision, its own code) at the
// real ray's exact locations start + n step, over the whole volume (its commands' `ray` is the
// hardware's and is not read). No memory model: it counts resamples only.
#pragma once

#include <memory>

#include "render/volume_engine.hpp"

namespace tmu::render {

std::unique_ptr<VolumeUnitEngine> make_ideal_volume_engine(const volume::VoxelGrid& grid);

}  // namespace tmu::render
