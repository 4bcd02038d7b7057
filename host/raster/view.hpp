// The camera's transforms as the rasterizer applies them: world to clip space (GLM, double,
// right-handed, depth 0..1) and clip space to pixels (y down).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace tmu::host {

glm::dmat4 view_projection(const Camera& camera);
glm::dvec2 to_screen(const glm::dvec4& clip, int width, int height);

}  // namespace tmu::host
