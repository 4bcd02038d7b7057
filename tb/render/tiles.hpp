// Splitting a frame into horizontal bands (`texsim render --tile i/n`) and joining them
// (`texsim merge`). A band is an image of the frame's width and its rows, carrying in its
// metadata (PNG text) which band of which frame it is, so merge can check that the bands cover
// the frame exactly once. The merged image equals the whole-frame render bit for bit: every
// fragment's colour depends on its own inputs only.
#pragma once

#include <string>
#include <vector>

#include "common/image.hpp"

namespace tmu::render {

struct Band {
  int index = 0, count = 1;  // band i of n
  int frame_width = 0, frame_height = 0;
  int row_begin = 0, row_end = 0;  // rows [begin, end) of the frame
};

// Band i of n of a frame of `height` rows: rows [i * height / n, (i + 1) * height / n).
Band band_of(int index, int count, int width, int height);
// The stem of a render's files: "render", or "render.tile-i-of-n" for band i of n > 1.
std::string band_stem(int index, int count);
// Parses "i/n" (0 <= i < n <= frame height); throws InputError naming --tile.
std::pair<int, int> parse_tile(const std::string& text);

void write_band(const std::string& path, const ImageRgb8& image, const Band& band);  // atomic
// Reads the bands, checks they are one frame's bands, each once, and joins them. Throws
// InputError naming the file and the problem.
ImageRgb8 merge_bands(const std::vector<std::string>& paths);

}  // namespace tmu::render
