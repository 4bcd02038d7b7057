// Which pixels a screen triangle covers. Vertices are snapped to 1/256 pixel (as rasterizer
// hardware does) and the edge functions are evaluated exactly in 64-bit integers, so the
// decision for a pixel centre on a shared edge is exact: with the top-left rule, a pixel centre
// on an edge belongs to the triangle for which that edge is a top or a left edge, and two
// triangles sharing an edge (or a mesh sharing a vertex) cover each pixel exactly once.
//
// Screen coordinates: x to the right, y downward, pixel (x, y) has its centre at
// (x + 0.5, y + 0.5).
#pragma once

#include <algorithm>
#include <cstdint>
#include <glm/glm.hpp>

namespace tmu::host {

inline constexpr int kSubpixelBits = 8;
inline constexpr int64_t kSubpixel = int64_t{1} << kSubpixelBits;

struct SubpixelPoint {
  int64_t x = 0, y = 0;
  friend bool operator==(const SubpixelPoint&, const SubpixelPoint&) = default;
};

// Rounds to the nearest 1/256 pixel; clamped to +-2^16 pixels so that the edge products stay
// far inside int64 (clipped triangles lie within the viewport anyway).
SubpixelPoint snap(const glm::dvec2& screen);

// Twice the signed area, (b - a) x (c - a): positive when a, b, c turn clockwise as seen on the
// screen (y down).
int64_t twice_area(const SubpixelPoint& a, const SubpixelPoint& b, const SubpixelPoint& c);

// Calls visit(x, y) for each pixel of rows [row_begin, row_end) and columns [0, width) whose
// centre the triangle covers, row by row, left to right. The triangle must have
// twice_area(a, b, c) > 0 (others cover nothing).
template <class Visit>
void for_each_covered_pixel(const SubpixelPoint& a, const SubpixelPoint& b, const SubpixelPoint& c,
                            int width, int row_begin, int row_end, Visit&& visit) {
  if (twice_area(a, b, c) <= 0) return;
  const SubpixelPoint v[3] = {a, b, c};
  // Edge i runs from v[i] to v[i + 1]; the interior is where every edge function is > 0.
  // Top edge: horizontal with the interior below (dy = 0, dx > 0); left edge: dy < 0. A centre
  // exactly on an edge (E = 0) counts only for top and left edges: E + 1 > 0 there.
  int64_t bias[3], step_x[3];
  for (int i = 0; i < 3; ++i) {
    const SubpixelPoint& p = v[i];
    const SubpixelPoint& q = v[(i + 1) % 3];
    const int64_t dx = q.x - p.x, dy = q.y - p.y;
    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
    bias[i] = top_left ? 1 : 0;
    step_x[i] = -dy * kSubpixel;
  }
  // Pixel centres (k + 0.5) inside the bounding box: ceil((min - half) / one) ..
  // floor((max - half) / one).
  const auto first_centre = [](int64_t lo) {
    const int64_t n = lo - kSubpixel / 2;
    return n >= 0 ? (n + kSubpixel - 1) / kSubpixel : -((-n) / kSubpixel);
  };
  const auto last_centre = [](int64_t hi) {
    const int64_t n = hi - kSubpixel / 2;
    return n >= 0 ? n / kSubpixel : -((-n + kSubpixel - 1) / kSubpixel);
  };
  const int64_t x0 = std::max<int64_t>(0, first_centre(std::min({a.x, b.x, c.x})));
  const int64_t x1 = std::min<int64_t>(width - 1, last_centre(std::max({a.x, b.x, c.x})));
  const int64_t y0 = std::max<int64_t>(row_begin, first_centre(std::min({a.y, b.y, c.y})));
  const int64_t y1 = std::min<int64_t>(row_end - 1, last_centre(std::max({a.y, b.y, c.y})));
  for (int64_t y = y0; y <= y1; ++y) {
    const int64_t py = y * kSubpixel + kSubpixel / 2;
    const int64_t px = x0 * kSubpixel + kSubpixel / 2;
    int64_t e[3];
    for (int i = 0; i < 3; ++i) {
      const SubpixelPoint& p = v[i];
      const SubpixelPoint& q = v[(i + 1) % 3];
      e[i] = (q.x - p.x) * (py - p.y) - (q.y - p.y) * (px - p.x) + bias[i];
    }
    for (int64_t x = x0; x <= x1; ++x) {
      if (e[0] > 0 && e[1] > 0 && e[2] > 0) visit(static_cast<int>(x), static_cast<int>(y));
      for (int i = 0; i < 3; ++i) e[i] += step_x[i];
    }
  }
}

}  // namespace tmu::host
