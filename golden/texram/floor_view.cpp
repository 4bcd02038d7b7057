#include "texram/floor_view.hpp"

#include <algorithm>
#include <cmath>

namespace tmu::texram {

std::vector<ViewRequest> floor_view(int width, int height, uint32_t texels_u, uint32_t texels_v,
                                    double tiles) {
  // Screen: sx in [-1, 1] across, sy in (0, 1] below the horizon (at 1/4 of the height). A
  // floor point at depth z = 1/sy projects there: u = a sx / sy, v = b / sy, so that the
  // bottom row spans `tiles` textures.
  const double horizon = 0.25 * height;
  const double a = tiles * texels_u / 2.0, b = 0.5 * texels_v;
  std::vector<ViewRequest> out;
  for (int y = static_cast<int>(std::ceil(horizon)); y < height; ++y) {
    const double sy = (y + 0.5 - horizon) / (height - horizon);
    for (int x = 0; x < width; ++x) {
      const double sx = (2.0 * (x + 0.5) - width) / width;
      ViewRequest r;
      r.x = x;
      r.y = y;
      r.u = a * sx / sy + texels_u / 2.0;
      r.v = b / sy;
      // Derivatives per pixel: d sx/dx = 2/width, d sy/dy = 1/(height - horizon).
      const double dudx = a * (2.0 / width) / sy;
      const double dsy = 1.0 / (height - horizon);
      const double dudy = -a * sx / (sy * sy) * dsy, dvdy = -b / (sy * sy) * dsy;
      const double footprint = std::max(std::abs(dudx), std::hypot(dudy, dvdy));
      r.lambda = std::log2(footprint);
      out.push_back(r);
    }
  }
  return out;
}

}  // namespace tmu::texram
