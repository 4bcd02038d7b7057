// The volume unit as the renderer sees it: commands (rays, or runs of a ray's locations) in,
// resamples out, and the memory's counters. The renderer casts through this interface only, so
// that the unit at any level plugs in: ideal (golden/volume/volume_ideal: double, the real
// ray), golden (golden/volume/unit: the access schedule, the page model). An hls or rtl engine
// wraps the co-simulated block when it lands (branch volume-block): its cast() runs the block
// over the commands as one stimulus and returns its outputs as the golden engine does.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "render/units.hpp"
#include "volume/marcher.hpp"
#include "volume/unit.hpp"
#include "volume/voxels.hpp"

namespace tmu::render {

// One command: locations first .. first + ray.count - 1 of a set-up ray.
struct VolumeCommand {
  volume::Ray ray;               // the hardware's: quantised, in the chip's own voxel coordinates
  glm::dvec3 start{0}, step{0};  // the real ray (the whole volume's coordinates; the ideal's)
  uint32_t first = 0;            // the index of ray.start's location along the real ray
};

// A resample as the host reads it: value 0..255 and gradient in voxel values per voxel (zero in
// value mode). The golden's are its port values exactly (integers, SQ9.4 / 16), so two hardware
// engines agree bit for bit exactly when their samples compare equal.
struct VolumeSample {
  double value = 0;
  glm::dvec3 gradient{0};
  friend bool operator==(const VolumeSample&, const VolumeSample&) = default;
};

struct VolumeCounters {
  uint64_t resamples = 0, accesses = 0, bank_reads = 0, page_faults = 0, slow_accesses = 0;
  // The unit's time at 30 ns an access and one more on a page fault (texram/page_model.hpp).
  double seconds() const;
  VolumeCounters& operator+=(const VolumeCounters& o);
  friend bool operator==(const VolumeCounters&, const VolumeCounters&) = default;
};

class VolumeUnitEngine {
 public:
  virtual ~VolumeUnitEngine() = default;
  // Every location of every command, in order (command 0's first).
  virtual std::vector<VolumeSample> cast(const std::vector<VolumeCommand>& commands) = 0;
  // Since construction.
  virtual VolumeCounters counters() const = 0;
  // Whether the counters model the memory (the ideal's count resamples only).
  virtual bool has_memory() const = 0;
};

// The engine of one chip at `level` over `grid` (the chip's voxels: one component of one slab).
// hls and rtl: std::runtime_error "volume unit: no hls/rtl engine yet" until the block lands.
std::unique_ptr<VolumeUnitEngine> make_volume_engine(Level level, const volume::VoxelGrid& grid,
                                                     const volume::Config& config);

// Thrown for hls and rtl (and checked before anything is written).
void require_volume_engine(Level level);

}  // namespace tmu::render
