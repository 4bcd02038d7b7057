// An object's model matrix: scale, then rotate about X, then Y, then Z, then translate, so
// M = T * Rz * Ry * Rx * S applied to column vectors.
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.hpp"

namespace tmu::host {

glm::dmat4 Transform::matrix() const {
  const glm::dmat4 identity(1.0);
  glm::dmat4 m = glm::translate(identity, translate);
  m = glm::rotate(m, glm::radians(rotate_deg.z), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotate_deg.y), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotate_deg.x), glm::dvec3(1, 0, 0));
  return glm::scale(m, scale);
}

}  // namespace tmu::host
