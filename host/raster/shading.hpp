// The shade I_d of 000 eq. 5 at a surface point: the lights of scenes/README.md summed and
// clamped to 0..1 per channel; 1 everywhere in a scene without lights.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.hpp"

namespace tmu::host {

// `normal` unit, world space; `position` world space.
glm::dvec3 shade(const std::vector<Light>& lights, const glm::dvec3& normal,
                 const glm::dvec3& position);

}  // namespace tmu::host
