#include "raster/shading.hpp"

#include <algorithm>

namespace tmu::host {

glm::dvec3 shade(const std::vector<Light>& lights, const glm::dvec3& normal,
                 const glm::dvec3& position) {
  if (lights.empty()) return glm::dvec3(1);
  glm::dvec3 sum(0);
  for (const Light& l : lights) {
    switch (l.kind) {
      case Light::Kind::kAmbient:
        sum += l.colour;
        break;
      case Light::Kind::kDirectional:
        // The direction is taken as a direction only: a scene writes [-1, -2, -1], not a
        // unit vector, and its length must not scale the light.
        sum += l.colour * std::max(0.0, glm::dot(normal, -glm::normalize(l.vector)));
        break;
      case Light::Kind::kPoint: {
        const glm::dvec3 to_light = l.vector - position;
        const double distance = glm::length(to_light);
        if (distance > 0) sum += l.colour * std::max(0.0, glm::dot(normal, to_light / distance));
        break;
      }
    }
  }
  return glm::clamp(sum, 0.0, 1.0);
}

}  // namespace tmu::host
