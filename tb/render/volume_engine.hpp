// The volume unit as the renderer sees it: commands (rays, or runs of a ray's locations) in,
// resamples out, and the memory's counters. The renderer casts through this interface only, so
// that the unit at any level plugs in: ideal (golden/volume/volume_ideal: double, the real
// ray), golden (golden/volume/unit: the access schedule, the page model), hls and rtl (the
// co-simulated block, render/volume_engine_block.hpp: its cast() runs the block's SystemC model
// or Verilated RTL over the commands in pieces and returns its outputs as golden does).
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
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
  uint64_t rays = 0;  // commands (a ray's run of locations on a chip)
  uint64_t resamples = 0, accesses = 0, bank_reads = 0, page_faults = 0, slow_accesses = 0;
  // The unit's time at 30 ns an access and one more on a page fault (texram/page_model.hpp).
  double seconds() const;
  VolumeCounters& operator+=(const VolumeCounters& o);
  friend bool operator==(const VolumeCounters&, const VolumeCounters&) = default;
};

// An hls or rtl engine's pieces, each compared unit by unit (harness/scoreboard.hpp) with the
// block at the reference level run over the same items from its own open pages: every output
// (value, gradient, last), every memory request and every counter.
struct VolumePieceCheck {
  std::string against;
  uint64_t pieces = 0, outputs = 0, requests = 0;
  uint64_t differing_pieces = 0;
  std::vector<std::string> first;  // the first differences, readable
  bool match() const { return differing_pieces == 0; }
  VolumePieceCheck& operator+=(const VolumePieceCheck& o);
};

struct VolumeEngineOptions {
  // hls, rtl: compare every piece with the block at this level (golden, hls or rtl).
  std::optional<Level> check;
  // hls, rtl: flip bit 0 of the value of this output of the engine (counted over all its
  // pieces), before anything reads it: proves that the checks can fail.
  int64_t inject_fault = -1;
  std::string name;  // for messages: "chip 2, component 0"
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
  // Clocked cycles of its runs (hls, rtl; 0 when untimed) and how many runs (pieces) it made.
  virtual uint64_t cycles() const { return 0; }
  virtual uint64_t pieces() const { return 0; }
  // With VolumeEngineOptions::check: its pieces' comparison.
  virtual std::optional<VolumePieceCheck> piece_check() const { return std::nullopt; }
};

// The engine of one chip at `level` over `grid` (the chip's voxels: one component of one slab).
std::unique_ptr<VolumeUnitEngine> make_volume_engine(Level level, const volume::VoxelGrid& grid,
                                                     const volume::Config& config,
                                                     const VolumeEngineOptions& options = {});

}  // namespace tmu::render
