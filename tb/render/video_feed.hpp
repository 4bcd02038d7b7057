// A scene's video map on its way into a chip (000 §11-12, docs/video.md "Rendering a video"):
// the source's frames (generated, render/video_pattern, or numbered image files) as the video
// port's items through the golden VideoMap at the chip's 512-cell rows (receiver -> one
// MipgenStream a plane -> page-row buffers and the arbiter -> the memory, the chip-side swap of
// the DRF's base), and the two buffers as they stand. The render's timing at the video's rate,
// and the reference the video unit's buffers (render/video_unit_feed, what the chip samples)
// must equal cell for cell.
//
// Time: a frame's items arrive at the video's rate (width x height x fps texels a second,
// video_rate), the sampler wanting every memory cycle meanwhile (the worst case for it: every
// write cycle is a cycle it loses, docs/video.md), and the feed runs on until the frame is
// swapped in and every row buffer is written. So after feed(k) the front buffer holds frame k.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/scene.hpp"
#include "texram/texture.hpp"
#include "texram/video/video_map.hpp"

namespace tmu::render {

// A video map's two buffers in the chip's memory: each one map of the video's layout (the
// buffer's cells of the VideoMap's memory), buffer 1 at buffer 0's base + VideoMap::buffer_stride;
// the DRF's base names `front`.
struct VideoBuffers {
  std::array<std::shared_ptr<const texram::TexramTexture>, 2> buffers;
  int front = 0;
  int shown = -1;        // the video frame the front buffer holds (-1: none yet, cells 0)
  bool by_unit = false;  // the video unit's writes (render/video_unit_feed), else golden's
};
// Per scene material, its video's buffers (null for a material without a video).
using VideoState = std::vector<std::shared_ptr<const VideoBuffers>>;

texram::video::VideoFormat video_format(const host::Video& video);
// Frame k of the video's source. Throws InputError naming the file for an unreadable file.
texram::video::VideoFrame video_frame(const host::Video& video, int k);
// Both buffers of cells 0, front 0: what the chip holds before the first frame.
std::shared_ptr<const VideoBuffers> empty_video_buffers(const host::Video& video);

// What feeding one frame did.
struct VideoFrameFeed {
  int frame = 0;     // the source's frame number
  uint64_t tag = 0;  // VideoMap's frame tag
  int buffer = 0;    // the buffer it was written to (and is shown from after its swap)
  bool complete = false;
  uint64_t begin_cycle = 0, end_cycle = 0, swap_cycle = 0;  // VideoMap's cycles
  uint64_t cycles = 0;                                      // cycles this feed ran
  // The arbiter's counters over those cycles.
  uint64_t sampler_wanted = 0, sampler_lost = 0, write_accesses = 0, write_cycles = 0,
           page_faults = 0, read_accesses = 0, read_cycles = 0, lost_writes = 0;
  uint64_t max_latency = 0;  // the most cycles a ready row buffer waited (the run so far)
};

class VideoFeed {
 public:
  // The video's two buffers at `base` of every bank, the DRF `drf` showing the front one.
  // Throws std::invalid_argument when the buffers do not fit a chip's bank.
  VideoFeed(const host::Video& video, uint32_t base, int drf);

  // Frame k of the source through the port, the generator and the row buffers until it is
  // swapped in. Throws std::logic_error when the memory cannot keep up (VideoMap's refusal).
  VideoFrameFeed feed(int k);
  // The buffers as the memory holds them now.
  std::shared_ptr<const VideoBuffers> buffers() const;
  const texram::video::VideoMap& map() const { return map_; }

 private:
  host::Video video_;
  texram::video::VideoMap map_;
  std::vector<int> frame_of_tag_{-1};  // the source's frame of each tag (tag 0: none)
};

}  // namespace tmu::render
