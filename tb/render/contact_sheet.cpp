#include "render/contact_sheet.hpp"

#include <algorithm>

namespace tmu::render {

ImageRgb8 contact_sheet(const std::vector<ImageRgb8>& frames) {
  const int n = static_cast<int>(frames.size());
  const int cols = std::min(n, 4), rows = (n + cols - 1) / cols;
  const int w = frames[0].width, h = frames[0].height, gap = 4;
  ImageRgb8 sheet(cols * (w + gap) + gap, rows * (h + gap) + gap);
  std::fill(sheet.pixels.begin(), sheet.pixels.end(), Rgb8{40, 40, 40});
  for (int i = 0; i < n; ++i) {
    const int ox = gap + (i % cols) * (w + gap), oy = gap + (i / cols) * (h + gap);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x)
        sheet.at(ox + x, oy + y) = frames[static_cast<size_t>(i)].at(x, y);
    }
  }
  return sheet;
}

}  // namespace tmu::render
