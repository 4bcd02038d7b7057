// The camera's transforms as the rasterizer applies them: world to clip space (GLM, double,
// right-handed, depth 0..1) and clip space to pixels (y down); and back, a screen point's ray.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace tmu::host {

glm::dmat4 view_projection(const Camera& camera);
glm::dvec2 to_screen(const glm::dvec4& clip, int width, int height);

// The ray from the eye through screen point (x, y) (pixels, y down, centres at i + 0.5):
// origin + lambda direction, direction ending on the far plane. The far plane is a plane of the
// eye's space, so direction is an affine function of (x, y).
struct Ray {
  glm::dvec3 origin{0}, direction{0};
};
Ray pixel_ray(const Camera& camera, double x, double y);

}  // namespace tmu::host
