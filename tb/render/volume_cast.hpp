// A volume scene's frame through the volume unit: the host sets up a ray per pixel, hands the
// unit the locations of every ray still open a segment at a time (each location to the chip
// whose slab owns it), classifies, shades and composites what comes back front to back, and
// stops a ray once it is opaque enough (host/volume/compositing.hpp). Rays are issued in rounds:
// round r holds segment r of every open ray in pixel order, each chip's share one batch, so that
// an hls or rtl engine runs a round as one stimulus; without early termination a round is the
// whole of every ray (one batch: the unit's order is then ray after ray).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "render/units.hpp"
#include "render/volume_engine.hpp"
#include "volume/ray_setup.hpp"
#include "volume/slabs.hpp"
#include "volume/volume_scene.hpp"

namespace tmu::render {

struct VolumeFrame {
  int width = 0, height = 0;
  std::vector<glm::dvec3> pixels;  // over the background, 0..1, row-major
  uint64_t rays = 0, rays_hit = 0, rays_terminated = 0;
  uint64_t locations = 0;   // set up: the sum of the rays' counts
  uint64_t issued = 0;      // locations sent to the unit (each resampled once a component)
  uint64_t composited = 0;  // resamples the host blended
  uint64_t rounds = 0;
  host::SlabPlan plan;
  std::vector<VolumeCounters> chips;  // per chip, its components' engines summed
  VolumeCounters total;
  // hls, rtl: per chip the clocked cycles of its block runs (its components' one after
  // another), and the runs (pieces) of all chips.
  std::vector<uint64_t> chip_cycles;
  uint64_t pieces = 0;
  // With VolumeCastOptions::check_units: every engine's pieces against the reference level.
  std::optional<VolumePieceCheck> unit_check;
  bool has_memory = false;
  double setup_s = 0, unit_s = 0, composite_s = 0;
  // The unit's time for the frame: the slowest chip's (the chips work at once), from the page
  // model's counts (an access a period, two on a fault).
  double unit_seconds() const;
  // hls, rtl: the slowest chip's clocked cycles at 30 ns a cycle (0 when untimed).
  double clocked_seconds() const;
};

struct VolumeCastOptions {
  VolumeCastOptions(Level level_ = Level::kGolden, int chips_ = 1,
                    std::vector<VolumeSample>* record_ = nullptr)
      : level(level_), chips(chips_), record(record_) {}
  Level level;
  int chips;  // the ideal reads the whole volume: always one
  // Every sample the engines returned, in the order they returned them (for the check).
  std::vector<VolumeSample>* record;
  // hls, rtl: run every piece at this level too and compare unit by unit
  // (VolumeEngineOptions::check).
  std::optional<Level> check_units;
  // hls, rtl: the output of chip 0's first component's engine whose value bit 0 is flipped.
  int64_t inject_fault = -1;
};

// The rays of a frame, one per pixel, row-major.
std::vector<host::RaySetup> set_up_rays(const host::VolumeScene& scene);

// `grids`: volume_grids(scene) (one raw grid, or R, G, B, A).
VolumeFrame cast_volume(const host::VolumeScene& scene, const std::vector<volume::VoxelGrid>& grids,
                        const std::vector<host::RaySetup>& rays, const VolumeCastOptions& options);

}  // namespace tmu::render
