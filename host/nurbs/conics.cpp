// The quadric nets of conics.hpp: one sweep of a weighted profile around the Y axis.
#include "nurbs/conics.hpp"

#include <cmath>

namespace tmu::host::nurbs {
namespace {

// A weighted planar polygon with its knots: the circle's (x, z) or a profile's (radius, y).
struct Net2 {
  std::vector<glm::dvec2> points;
  std::vector<double> weights;
  std::vector<double> knots;
  int degree = 2;
};

const double kCorner = std::sqrt(2.0) / 2;

// The unit circle in 9 points from (1, 0), turning toward the second coordinate's +1.
Net2 unit_circle() {
  return {{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}},
          {1, kCorner, 1, kCorner, 1, kCorner, 1, kCorner, 1},
          {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}};
}

// The profile swept around Y by the unit circle: s is the circle, t the profile.
Patch revolve(const Net2& profile) {
  const Net2 circle = unit_circle();
  Patch patch;
  patch.degree_s = circle.degree;
  patch.degree_t = profile.degree;
  patch.count_s = static_cast<int>(circle.points.size());
  patch.count_t = static_cast<int>(profile.points.size());
  patch.knots_s = circle.knots;
  patch.knots_t = profile.knots;
  for (std::size_t j = 0; j < profile.points.size(); ++j) {
    for (std::size_t i = 0; i < circle.points.size(); ++i) {
      const glm::dvec2 c = circle.points[i], r = profile.points[j];
      patch.points.emplace_back(r.x * c.x, r.y, r.x * c.y);
      patch.weights.push_back(circle.weights[i] * profile.weights[j]);
    }
  }
  return patch;
}

}  // namespace

Patch sphere(double radius) {
  const double r = radius;
  return revolve({{{0, r}, {r, r}, {r, 0}, {r, -r}, {0, -r}},
                  {1, kCorner, 1, kCorner, 1},
                  {0, 0, 0, 0.5, 0.5, 1, 1, 1}});
}

Patch torus(double major, double minor) {
  // The unit circle turned so that it starts at (1, 0) and goes toward -y, then scaled and moved.
  Net2 tube = unit_circle();
  for (glm::dvec2& p : tube.points) p = glm::dvec2(major + minor * p.x, -minor * p.y);
  return revolve(tube);
}

Patch cylinder(double radius, double height) {
  return revolve({{{radius, height / 2}, {radius, -height / 2}}, {1, 1}, {0, 0, 1, 1}, 1});
}

}  // namespace tmu::host::nurbs
