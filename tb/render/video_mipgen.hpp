// The mipmap generator block (tmu_mipgen, tb/blocks/mipgen) over a video frame at the render's
// engine, against the golden video path: the block's cell writes for every plane of frame k (in
// the video's source order, interlaced too) must be exactly the cells the golden VideoMap left in
// the buffer that shows frame k. At rtl the pyramid's arithmetic so runs as hardware; the port,
// the row buffers and the swap stay golden (named as host work).
#pragma once

#include <cstdint>

#include "render/units.hpp"
#include "render/video_feed.hpp"

namespace tmu::render {

struct VideoMipgenCheck {
  uint64_t writes = 0;         // the block's cell writes, all planes
  uint64_t golden_writes = 0;  // golden mipgen_frame's (each cell of the layout once)
  uint64_t differing = 0;      // writes whose value differs from the front buffer's cell
  uint64_t cycles = 0;         // the block's cycles, all planes
  double seconds = 0;
  bool match() const { return differing == 0 && writes == golden_writes; }
};

// Runs the mipgen block at `level` over frame `frame` of `video` (plane by plane) and compares its
// writes with the cells of `buffers`' front buffer, which must hold that frame.
VideoMipgenCheck check_video_mipgen(const host::Video& video, int frame,
                                    const VideoBuffers& buffers, Level level);

}  // namespace tmu::render
