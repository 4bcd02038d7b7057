// `texsim render SCENE --chips N --frames A:B` of a scene with a video map (000 §11-12;
// docs/video.md "Rendering a video"): an animation in which the video maps change every frame.
//
// For each frame f from 0 to B, every video's frame f goes through the golden VideoMap
// (render/video_feed: port items -> one MipgenStream a plane -> page-row buffers and the arbiter
// -> the chip's memory, then the chip-side swap of the DRF's base). The time: the pixel pass of
// frame f starts once video frame f has been fed and swapped in (the feed runs until the swap),
// so render f samples video frame f's pyramid, complete, through the DRF's base as the swap left
// it; the other buffer holds frame f - 1, where frame f + 1 will be written. Frames A..B are
// rendered (render_scene at the engine, through the chips; --check compares each frame bit for
// bit), frames before A only fed. At hls and rtl the chip samples as hardware, and the mipgen
// block runs at the engine over each rendered frame, its writes compared with the front buffer's
// cells (render/video_mipgen); the rest of the video stream (port, row buffers, swap) stays golden
// on the host and the report names it (host work).
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
#include "render/video_mipgen.hpp"
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
  // ... and the mipgen block at the engine over that frame against the front buffer's cells
  std::vector<VideoMipgenCheck> mipgen;
  RenderReport render;
};

struct VideoRenderReport {
  std::string scene, engine, out_dir;
  int chips = 0, first = 0, last = 0;
  std::vector<std::string> videos;  // per video material: "screen: 64x64 generated bars, ..."
  std::vector<uint32_t> bases;      // per video material: buffer 0's cell in its chip's banks
  std::vector<int> drfs;            // ... and the DRF whose base the swap writes
  std::vector<VideoFrameReport> frames;
  std::string text() const;
  std::string json() const;
  bool match() const;
};

// Renders frames range.first..range.last (last -1: every frame of the video) into out_dir.
// Returns 0, or 1 when a checked frame or a mipgen comparison mismatched; throws InputError on bad
// input (before writing anything).
int render_video(const std::string& scene_path, const RenderOptions& options, FrameRange range,
                 std::ostream& log, VideoRenderReport* report = nullptr);

}  // namespace tmu::render
