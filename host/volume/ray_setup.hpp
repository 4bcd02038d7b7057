// Ray set-up for the volume unit (000 §13: "evenly spaced resample locations along an
// arbitrarily oriented viewing ray"): per pixel a ray from the eye, its entry into and exit from
// the volume's box, and the unit's command: the first location, the step vector and the count,
// quantised to the unit's port formats (VoxelPos SQ10.16, VoxelStep SQ4.16, VoxelCount).
//
// Coordinates: voxels, voxel centres at integers; the box is the voxel centres' hull
// [0, X-1] x [0, Y-1] x [0, Z-1] (beyond it the unit clamps to the faces: nothing new to see).
// The scene's world places the box centred on the origin with its longest side 2 units long,
// the voxel axes along the world's: voxel = (size - 1) / 2 + world (max(size) - 1) / 2, so
// that a camera a few units away sees any volume whole, and directions are the same in both.
//
// The locations: the first on the entry point (the eye itself when it is inside the box), then
// every `step` voxels along the ray while within the exit point (a location exactly on it
// included, with 1e-9 of a step for the rounding of the entry and exit):
//   count = floor((exit - entry) / step + 1e-9) + 1, 0 for a ray that misses the box.
// A ray grazing a face, an edge or a corner has entry = exit and one location there.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "scene/scene.hpp"
#include "volume/marcher.hpp"

namespace tmu::host {

// The camera in voxel coordinates.
struct VolumeView {
  glm::dvec3 eye{0};                                          // voxels
  glm::dvec3 forward{0, 0, -1}, right{1, 0, 0}, up{0, 1, 0};  // unit vectors
  double tan_half = 1, aspect = 1;
  int width = 1, height = 1;
};
VolumeView make_view(const Camera& camera, const std::array<uint32_t, 3>& size);
glm::dvec3 world_to_voxel(const glm::dvec3& world, const std::array<uint32_t, 3>& size);
// The unit direction of the ray through the centre of pixel (x, y), row 0 at the top.
glm::dvec3 pixel_direction(const VolumeView& view, int x, int y);

// Where the ray origin + t dir (t >= 0) is inside the box [0, hi]: entry <= t <= exit.
struct BoxHit {
  bool hit = false;
  double entry = 0, exit = 0;
};
BoxHit intersect_box(const glm::dvec3& hi, const glm::dvec3& origin, const glm::dvec3& dir);

struct RaySetup {
  glm::dvec3 start{0}, step{0};  // voxels: the real ray's first location and step vector
  uint32_t count = 0;            // resample locations; 0: the ray misses the volume
  volume::Ray ray;               // the unit's command: start and step quantised, the count
};

// `dir` a unit vector, `step` in voxels (kMinStep..kMaxStep of volume_scene.hpp).
RaySetup set_up_ray(const std::array<uint32_t, 3>& size, const glm::dvec3& origin,
                    const glm::dvec3& dir, double step);

}  // namespace tmu::host
