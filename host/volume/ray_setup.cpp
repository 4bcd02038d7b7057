#include "volume/ray_setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tmu::host {

glm::dvec3 world_to_voxel(const glm::dvec3& world, const std::array<uint32_t, 3>& size) {
  const double scale = (std::max({size[0], size[1], size[2]}) - 1) / 2.0;
  return glm::dvec3(size[0] - 1, size[1] - 1, size[2] - 1) / 2.0 + world * scale;
}

VolumeView make_view(const Camera& camera, const std::array<uint32_t, 3>& size) {
  VolumeView v;
  v.eye = world_to_voxel(camera.position, size);
  v.forward = glm::normalize(camera.target - camera.position);
  v.right = glm::normalize(glm::cross(v.forward, camera.up));
  v.up = glm::cross(v.right, v.forward);
  v.tan_half = std::tan(camera.fov_deg * M_PI / 360);
  v.aspect = static_cast<double>(camera.width) / camera.height;
  v.width = camera.width;
  v.height = camera.height;
  return v;
}

glm::dvec3 pixel_direction(const VolumeView& v, int x, int y) {
  const double sx = (2 * (x + 0.5) / v.width - 1) * v.tan_half * v.aspect;
  const double sy = (1 - 2 * (y + 0.5) / v.height) * v.tan_half;
  return glm::normalize(v.forward + v.right * sx + v.up * sy);
}

BoxHit intersect_box(const glm::dvec3& hi, const glm::dvec3& origin, const glm::dvec3& dir) {
  double entry = 0, exit = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (dir[a] == 0) {
      // Parallel to the faces of this axis: inside their slab for every t, or never.
      if (origin[a] < 0 || origin[a] > hi[a]) return {};
      continue;
    }
    const double t0 = (0 - origin[a]) / dir[a], t1 = (hi[a] - origin[a]) / dir[a];
    entry = std::max(entry, std::min(t0, t1));
    exit = std::min(exit, std::max(t0, t1));
  }
  if (entry > exit) return {};
  return {true, entry, exit};
}

RaySetup set_up_ray(const std::array<uint32_t, 3>& size, const glm::dvec3& origin,
                    const glm::dvec3& dir, double step) {
  RaySetup r;
  const glm::dvec3 hi(size[0] - 1, size[1] - 1, size[2] - 1);
  const BoxHit hit = intersect_box(hi, origin, dir);
  if (!hit.hit) return r;
  const double n = std::floor((hit.exit - hit.entry) / step + 1e-9) + 1;
  if (n > 65535) throw std::invalid_argument("ray set-up: more than 65535 locations");
  r.count = static_cast<uint32_t>(n);
  r.start = origin + dir * hit.entry;
  r.step = dir * step;
  for (int a = 0; a < 3; ++a) {
    r.ray.start[static_cast<size_t>(a)] = volume::quantise(r.start[a]);
    r.ray.step[static_cast<size_t>(a)] = volume::quantise(r.step[a]);
  }
  r.ray.count = r.count;
  if (!volume::ray_in_range(r.ray))
    throw std::logic_error("ray set-up: a ray out of the unit's range");
  return r;
}

}  // namespace tmu::host
