// The video unit (tb/blocks/video_unit; rtl/texram/tmu_video_unit.sv) at the render's engine
// writes a scene's video into the chip's memory (000 §11-12, docs/video.md "Rendering a video"):
// the unit at the chip's rows of a page (rtl variant "page"), the source's frames as the port's
// items, a texel every cycle or every few where the rows need it (tb::video_unit_feed_items; the
// sampler leaves the memory to the unit, as the render's pixel pass runs between two frames'
// feeds), each frame until it is swapped in; the unit's memory requests (its row writes, a
// row's 8-cell words) replayed into the two buffers, as they stand at each swap, are what the
// chip samples. At the scene's rate (64 x 64 at 30 fps: a texel every 271 cycles) a frame would
// take a million cycles more of nothing: the cells and the swap are the same at any rate the memory
// keeps up with, and the scene rate's timing is the golden VideoFeed's (render/video_feed).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "harness/scoreboard.hpp"
#include "render/units.hpp"
#include "render/video_feed.hpp"
#include "scene/scene.hpp"

namespace tmu::render {

// What the unit did for one frame: from its first item to its swap.
struct VideoUnitFrame {
  std::shared_ptr<const VideoBuffers> buffers;  // the memory's two buffers after its swap
  uint64_t cycles = 0;                          // memory cycles (the unit's cycle items)
  uint64_t writes = 0, reads = 0;               // row accesses
};

struct VideoUnitFeed {
  std::vector<VideoUnitFrame> frames;   // video frames 0..last
  size_t items = 0, cycles = 0;         // the unit's run: its items, its memory cycles
  int cycles_per_item = 1;              // the port's rate in its run: a texel in this many cycles
  std::optional<tb::Comparison> check;  // against the check level's run of the same items
  std::string check_level;
};

// Runs the video unit at `level` over frames 0..last of `video`, its buffer 0 at `base` of every
// bank and buffer 1 where VideoMap puts it; with `check`, at that level too, compared output by
// output, request by request and counter by counter. Throws InputError naming the video for a
// format the unit cannot take (std::runtime_error from the block).
VideoUnitFeed feed_video_unit(const host::Video& video, uint32_t base, int last, Level level,
                              std::optional<Level> check);

// Cells of `a`'s two buffers that differ from `b`'s, and whether the fronts differ (counted as one
// cell more).
uint64_t differing_cells(const VideoBuffers& a, const VideoBuffers& b);

}  // namespace tmu::render
