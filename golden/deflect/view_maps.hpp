// The maps the deflection chain reads, computed by the host in the view frame (x = v_side,
// y = v_up, z = v_dir towards the viewer; coord_tables.hpp): the diffuse and specular shading
// maps of 001 §2.3 (eq. 9-10) for the scene's lights, the spherical environment map and the
// cube faces of 000 §7. The host recomputes them when the view changes.
//
// Sphere maps (shading maps, spherical environment), side S = 2^s, 128 <= S <= 1024: texel
// (i, j) holds the normal N = (x, y, sqrt(1 - x^2 - y^2)) with x = 2 (i + 0.5) / S - 1,
// y = 1 - 2 (j + 0.5) / S (outside the disc, the rim's normal), i.e. they are read at the
// normal's (uN, vN) like the mirror ball of 001 §2 eq. 4-5: the trilinear unit's sphere
// addressing (texram::texel_request) reads a map there, u = (uN + 1) / 2 S, v = (1 - vN) / 2 S. The
// diffuse map holds the sum of the lights' diffuse terms at N; the specular map the specular term
// at R = 2 (N . E) N - E, E = (0, 0, 1); the spherical environment the environment in direction R.
// A map over (uR, vR) alone could not tell R from its mirror image through the view plane (wR < 0
// and wR > 0 read the same texel); the cube map takes all of R.
//
// Cube faces, side 2^L: OpenGL's convention (cube_map.hpp): texel (i, j) of face f looks in
// the direction whose face coordinates are sc = 2 (i + 0.5) / 2^L - 1, tc = 2 (j + 0.5) / 2^L - 1.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "common/image.hpp"

namespace tmu::deflect {

// A light as the shading maps see it: in the view frame, from far away.
struct MapLight {
  bool ambient = false;
  glm::dvec3 towards{0, 0, 1};  // unit, from the surface to the light
  glm::dvec3 colour{1};
};

// A direction in the view frame -> colour.
using Environment = std::function<Rgb8(const glm::dvec3& direction)>;

// The normal texel (i, j) of a sphere map of side `side` stands for.
glm::dvec3 sphere_map_normal(int side, int i, int j);
// R = 2 (N . E) N - E with E = (0, 0, 1).
glm::dvec3 view_reflection(const glm::dvec3& normal);

ImageRgb8 diffuse_map(int side, const std::vector<MapLight>& lights);
// k_spec (R . L)^n summed over the lights that are not ambient.
ImageRgb8 specular_map(int side, const std::vector<MapLight>& lights, const glm::dvec3& k_spec,
                       double exponent);
ImageRgb8 sphere_environment(int side, const Environment& environment);
// Faces +X, -X, +Y, -Y, +Z, -Z.
std::array<ImageRgb8, 6> cube_environment(int face_log2, const Environment& environment);
glm::dvec3 cube_face_direction(uint32_t face, double sc, double tc);

// The built-in room every environment map shows without an image: a sky brightening towards
// the zenith, a checkered ground (sharp edges show direction errors) and a sun; `direction`
// in world space (y up).
Rgb8 sky_room(const glm::dvec3& direction);

}  // namespace tmu::deflect
