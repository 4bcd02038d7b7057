// The video unit of the TEXRAM (000 §11-12; docs/video.md) as the chip has it: a VideoMap for
// each configuration, and counters that run on across configurations, as the unit's registers
// do. A configuration with a new format or new buffer bases starts a new video map (front buffer
// 0, tags from 1, the shift registers and the row buffers empty: the driver reconfigures a
// drained unit); one that changes only the arbiter's bounds takes effect at the next cycle.
#pragma once

#include <cstdint>
#include <memory>

#include "texram/video/video_map.hpp"

namespace tmu::texram::video {

class VideoUnit {
 public:
  // Throws std::invalid_argument for a configuration VideoMap refuses, and std::logic_error for
  // a new video map while the port has a frame under way (its place would have no meaning).
  void configure(const VideoMapConfig& config);

  bool configured() const { return map_ != nullptr; }
  VideoMap& map() { return *map_; }
  const VideoMap& map() const { return *map_; }

  void receive(const VideoItem& item) { map_->receive(item); }
  bool cycle(bool sampler_wants) {
    const bool granted = map_->cycle(sampler_wants);
    shown_ += map_->swapped();
    return granted;
  }

  // The unit's counters, over every video map so far.
  struct Counts {
    uint64_t shown = 0;    // swaps
    uint64_t dropped = 0;  // frames the port dropped (malformed)
    uint64_t overruns = 0, late_reads = 0, lost_writes = 0;
    uint64_t forced = 0;  // accesses that took a cycle the sampler wanted
  };
  Counts counts() const;

 private:
  std::unique_ptr<VideoMap> map_;
  Counts before_;  // the counts of the maps before this one
  uint64_t shown_ = 0;
};

}  // namespace tmu::texram::video
