// `texsim render SCENE --chips N --frames A:B` of a scene with a video map (000 §11-12;
// docs/video.md "Rendering a video"): an animation in which the video maps change every frame.
//
// The video unit (render/video_unit_feed: the video_unit block, tmu_video_unit at rtl: port ->
// a mipmap generator a plane -> page-row buffers and the arbiter -> the memory, the swap of the
// front buffer) runs at the engine over every video's frames 0..B; the memory its writes leave at
// frame f's swap is what the chip samples for frame f. Beside it, the golden VideoMap
// (render/video_feed, the chip's 512-cell rows) feeds each frame at the video's rate for the
// timing figures, and the two buffers it leaves must equal the unit's, cell for cell. The time:
// the pixel pass of frame f starts once video frame f has been fed and swapped in, so render f
// samples video frame f's pyramid, complete, through the DRF's base as the swap left it; the
// other buffer holds frame f - 1, where frame f + 1 will be written. Frames A..B are rendered
// (render_scene at the engine, through the chips; --check compares each frame bit for bit, and
// the unit's run with the reference level's), frames before A only fed.
//
// Writes OUT/video.frame-NNNN.png, each frame's render report (video.frame-NNNN.report.*), the
// frames side by side (video.contact.png) and OUT/video.report.{json,txt}: per frame the video
// frame shown, its buffer, its cycles (first item, last item, swap), the sampler cycles lost to the
// video's writes and reads, the chip's cycles and the check's verdict.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "render/flyover.hpp"
#include "render/render.hpp"
#include "render/video_feed.hpp"
#include "scene/scene.hpp"

namespace tmu::render {

// Whether a material of the scene file has a "video" (loads the scene: InputError on a bad one).
bool is_video_scene(const std::string& scene_path);

// One rendered frame.
struct VideoFrameReport {
  int frame = 0;
  std::vector<VideoFrameFeed> feeds;  // per video material, what feeding its frame did
  std::vector<int> shown;             // per video material, the video frame the render sees
  std::vector<int> front;             // ... and the buffer the DRF's base names
  // ... and what the video unit at the engine did for it
  struct Unit {
    uint64_t cycles = 0, writes = 0, reads = 0;
    uint64_t differing = 0;     // cells of its two buffers (and the front) not the golden path's
    bool same_accesses = true;  // its row writes and reads are the golden path's (same rows)
  };
  std::vector<Unit> unit;
  RenderReport render;
};

struct VideoRenderReport {
  std::string scene, engine, out_dir;
  int chips = 0, first = 0, last = 0;
  std::vector<std::string> videos;  // per video material: "screen: 64x64 generated bars, ..."
  std::vector<uint32_t> bases;      // per video material: buffer 0's cell in its chip's banks
  std::vector<int> drfs;            // ... and the DRF whose base the swap writes
  struct UnitRunReport {
    size_t items = 0, cycles = 0;  // the video unit's items (port items and memory cycles)
    int cycles_per_item = 1;       // the port's rate: a texel in this many cycles
    std::string against;           // the check's reference level ("" unchecked)
    bool match = true;             // its outputs, requests and counters equal the reference's
  };
  std::vector<UnitRunReport> units;  // per video material
  std::vector<VideoFrameReport> frames;
  std::string text() const;
  std::string json() const;
  bool match() const;
};

// Renders frames range.first..range.last (last -1: every frame of the video) into out_dir.
// Returns 0, or 1 when a checked frame or the video unit's check mismatched, or the unit's memory
// is not the golden path's; throws InputError on bad input (before writing anything).
int render_video(const std::string& scene_path, const RenderOptions& options, FrameRange range,
                 std::ostream& log, VideoRenderReport* report = nullptr);

}  // namespace tmu::render
