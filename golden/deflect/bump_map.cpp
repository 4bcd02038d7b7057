#include "deflect/bump_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "deflect/deflect_ideal.hpp"

namespace tmu::deflect {

SphereAngle bump_texel(const SphereGrid& g, double du, double dv) {
  const ideal::Angles a = ideal::bump_angles({-du, -dv, 1.0});
  const auto steps = [&](double rad) { return std::llround(rad / g.step()); };
  const auto mag = std::min<long long>(std::llabs(steps(a.theta)), g.quarter() - 1);
  return {static_cast<uint32_t>(steps(a.phi)) & g.phi_mask(),
          make_theta(g, a.theta < 0, static_cast<uint32_t>(mag))};
}

Rgb8 pack_bump(const SphereGrid& g, SphereAngle t) {
  return {static_cast<uint8_t>(t.phi & 0xFF), static_cast<uint8_t>(theta_mag(g, t.theta)),
          static_cast<uint8_t>((theta_negative(g, t.theta) ? 0x80 : 0) | ((t.phi >> 8) & 0x7F))};
}

SphereAngle unpack_bump(const SphereGrid& g, Rgb8 c) {
  const uint32_t phi = (c.r | (uint32_t{c.b & 0x7Fu} << 8)) & g.phi_mask();
  return {phi, make_theta(g, (c.b & 0x80) != 0, std::min<uint32_t>(c.g, g.quarter() - 1))};
}

glm::dvec2 bump_slope(const ImageRgb8& heights, int x, int y, double scale) {
  const int w = heights.width, h = heights.height;
  const auto height = [&](int hx, int hy) {
    const Rgb8 c = heights.at((hx + w) % w, (hy + h) % h);
    return (c.r + c.g + c.b) / (3.0 * 255.0);
  };
  return {(height(x + 1, y) - height(x - 1, y)) / 2 * scale,
          (height(x, y - 1) - height(x, y + 1)) / 2 * scale};
}

ImageRgb8 bump_map_from_heights(const ImageRgb8& heights, double scale, const SphereGrid& g) {
  ImageRgb8 out(heights.width, heights.height);
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      const glm::dvec2 s = bump_slope(heights, x, y, scale);
      out.at(x, y) = pack_bump(g, bump_texel(g, s.x, s.y));
    }
  }
  return out;
}

}  // namespace tmu::deflect
