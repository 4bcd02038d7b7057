#include "texram/video/video_unit.hpp"

#include <stdexcept>
#include <string>

namespace tmu::texram::video {

void VideoUnit::configure(const VideoMapConfig& c) {
  auto next = std::make_unique<VideoMap>(c);
  if (map_ && next->config().format == map_->config().format &&
      next->buffer_base(0) == map_->buffer_base(0) &&
      next->buffer_base(1) == map_->buffer_base(1)) {
    map_->set_waits(c.arbiter.max_wait, c.arbiter.read_wait);  // the same map: new bounds only
    return;
  }
  if (map_ && map_->receiver().in_frame()) {
    throw std::logic_error("a new video map written in the middle of a frame (at " +
                           std::to_string(map_->receiver().stats().items) +
                           " items; a driver writes it between frames)");
  }
  if (map_) before_ = counts();
  map_ = std::move(next);
}

VideoUnit::Counts VideoUnit::counts() const {
  Counts c = before_;
  c.shown = shown_;
  if (!map_) return c;
  const ArbiterStats& s = map_->row_buffers().stats();
  c.dropped += map_->receiver().stats().frames_dropped;
  c.overruns += map_->overruns();
  c.late_reads += map_->late_reads();
  c.lost_writes += s.lost_writes;
  c.forced += s.forced_writes;
  return c;
}

}  // namespace tmu::texram::video
