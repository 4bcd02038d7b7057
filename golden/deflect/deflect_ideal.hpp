// The ideal (double precision) reference of the deflection units: exact normals, exact
// rotation of the bump vector onto the surface, exact reflection vector and map coordinates,
// with the frames and angle conventions of sphere_grid_definition.hpp and s2s_map.hpp. Tests
// and `texsim sweep deflection` measure the golden units' angle errors against it.
//
// It shares with golden only the definitions of sphere_grid_definition.hpp (the grid's sizes
// and step, the angles' port fields) and view_frame_definition.hpp (the view frame); all
// arithmetic, the angles' decoding included, is its own.
#pragma once

#include <glm/vec3.hpp>

#include "deflect/sphere_grid_definition.hpp"
#include "deflect/view_frame_definition.hpp"

namespace tmu::deflect::ideal {

struct Angles {
  double phi = 0, theta = 0;  // radians, eq. 12
};

// eq. 12 both ways; the zero vector and the poles give phi = 0.
glm::dvec3 to_vector(const Angles& a);
Angles to_angles(const glm::dvec3& v);
// A grid angle's value (nodes: phi = p d, theta = +-m d).
Angles grid_angles(const SphereGrid& grid, SphereAngle a);
glm::dvec3 grid_vector(const SphereGrid& grid, SphereAngle a);

// The bump texel's unit vector in the bump frame (u, v, w), and back.
glm::dvec3 bump_vector(const Angles& bump);
Angles bump_angles(const glm::dvec3& d_uvw);

// The bump frame on a surface with normal angles n, and D rotated into object space:
// R_y(phi_N) R_x(-theta_N) D.
glm::dvec3 deflect(const Angles& normal, const Angles& bump);

// Shading-map coordinates and reflection vector (eq. 17-22) from an exact unit normal.
struct Coords {
  double un = 0, vn = 0, ur = 0, vr = 0, wr = 0;
};
Coords map_coords(const ViewFrame& view, const glm::dvec3& n);

// The angle between two directions in degrees (0 when either is zero).
double angle_deg(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace tmu::deflect::ideal
