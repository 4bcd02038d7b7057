#include "raster/coverage.hpp"

#include <cmath>

namespace tmu::host {

namespace {
constexpr double kLimit = 65536.0 * kSubpixel;
}  // namespace

SubpixelPoint snap(const glm::dvec2& screen) {
  const auto one = [](double v) {
    const double s = std::clamp(v * static_cast<double>(kSubpixel), -kLimit, kLimit);
    return static_cast<int64_t>(std::nearbyint(std::isnan(s) ? 0.0 : s));
  };
  return {one(screen.x), one(screen.y)};
}

int64_t twice_area(const SubpixelPoint& a, const SubpixelPoint& b, const SubpixelPoint& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

}  // namespace tmu::host
