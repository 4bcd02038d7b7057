// The volume unit's hls and rtl engines in a render: the co-simulated block that `texsim cosim
// volume` and the conformance suite run (tb/blocks/volume/volume_block.hpp: its SystemC model
// hls/volume/volume_sc.hpp, its Verilated RTL rtl/volume/tmu_volume.sv, its TEXRAM memory),
// holding one chip's voxels (one component of one slab).
//
// cast() runs the commands through the block in pieces of at most kVolumePieceResamples
// resamples (whole commands; a command longer than that is a piece of its own): each piece one
// run of the block (a configuration item, then its rays), so that a frame's stimulus and the
// records of a checked run stay small. The memory of each piece starts with the pages the
// previous piece left open (read from the engine's own memory requests), so the counters of the
// pieces add up to those of one long run. With VolumeEngineOptions::check each piece is also
// run at the reference level (from the reference's own open pages) and compared by the
// co-simulation scoreboard: every output, memory request and counter.
#pragma once

#include <cstdint>
#include <memory>

#include "render/volume_engine.hpp"

namespace tmu::render {

// The most resamples of a piece (a command of more is a piece alone).
inline constexpr uint64_t kVolumePieceResamples = 16384;

// `level`: hls or rtl.
std::unique_ptr<VolumeUnitEngine> make_block_volume_engine(Level level,
                                                           const volume::VoxelGrid& grid,
                                                           const volume::Config& config,
                                                           const VolumeEngineOptions& options);

}  // namespace tmu::render
