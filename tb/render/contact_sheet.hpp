// Every frame of an animation side by side (the fly-over's and a video scene's contact sheets):
// up to four a row, in order, on a dark grey ground with a gap of 4 pixels.
#pragma once

#include <vector>

#include "common/image.hpp"

namespace tmu::render {

// The frames must be of one size and at least one.
ImageRgb8 contact_sheet(const std::vector<ImageRgb8>& frames);

}  // namespace tmu::render
