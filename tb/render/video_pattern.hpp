// The generated video sources of a scene's "video" key (scenes/README.md "Video maps"): frame
// number in, texels out, deterministic, integer only, so every engine and every run sees the same
// frames. Each moves visibly from frame to frame, so a render that shows the wrong frame differs.
#pragma once

#include <cstdint>
#include <string>

#include "texram/video/video_port.hpp"

namespace tmu::render {

// Frame `k` of the generated video `pattern` at `format`'s size and planes:
//   bars:  eight colour bars (white, yellow, cyan, green, magenta, red, blue, black) scrolling
//          left by 1/16 of the width a frame, over a dark band that scrolls down a line a frame;
//   rings: rings around a centre that walks a circle of 1/4 of the size in 16 frames, moving
//          out by 8 levels a frame;
//   noise: docs/video.md's test frame (video::test_frame: a ramp shifted by 7 k, xor'd noise).
// One plane: the luminance of the colour ((77 R + 150 G + 29 B + 128) >> 8); four: R G B and
// A = 255. Throws std::invalid_argument for another pattern.
texram::video::VideoFrame generated_video_frame(const std::string& pattern,
                                                const texram::video::VideoFormat& format,
                                                uint32_t k);

}  // namespace tmu::render
