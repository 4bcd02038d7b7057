#include "deflect/deflect_ideal.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace tmu::deflect::ideal {

glm::dvec3 to_vector(const Angles& a) {
  return {std::cos(a.theta) * std::sin(a.phi), std::sin(a.theta),
          std::cos(a.phi) * std::cos(a.theta)};
}

Angles to_angles(const glm::dvec3& v) {
  const double len = glm::length(v);
  if (len == 0) return {};
  const double phi = (v.x == 0 && v.z == 0) ? 0.0 : std::atan2(v.x, v.z);
  return {phi, std::asin(std::clamp(v.y / len, -1.0, 1.0))};
}

Angles grid_angles(const SphereGrid& g, SphereAngle a) {
  // The port fields by their definition: phi counts nodes modulo 4Q; theta's magnitude is its
  // value modulo Q, its sign the next bit (bits above are not part of the field).
  // A signed integer count, so that -0 (sign set, magnitude 0) is the angle 0, not -0.0.
  const int64_t q = g.quarter();
  const int64_t mag = a.theta % q;
  const bool negative = (a.theta / q) % 2 == 1;
  return {static_cast<double>(a.phi % (4 * q)) * g.step(),
          static_cast<double>(negative ? -mag : mag) * g.step()};
}

glm::dvec3 grid_vector(const SphereGrid& g, SphereAngle a) { return to_vector(grid_angles(g, a)); }

glm::dvec3 bump_vector(const Angles& b) {
  return {std::sin(b.theta), -std::cos(b.theta) * std::sin(b.phi),
          std::cos(b.theta) * std::cos(b.phi)};
}

Angles bump_angles(const glm::dvec3& d) {
  const double len = glm::length(d);
  if (len == 0) return {};
  return {std::atan2(-d.y, d.z), std::asin(std::clamp(d.x / len, -1.0, 1.0))};
}

glm::dvec3 deflect(const Angles& n, const Angles& b) {
  const glm::dvec3 d = bump_vector(b);
  // R_x(-theta_N): takes +z towards +y by theta_N.
  const double ct = std::cos(n.theta), st = std::sin(n.theta);
  const glm::dvec3 r{d.x, d.y * ct + d.z * st, -d.y * st + d.z * ct};
  // R_y(phi_N): takes +z towards +x by phi_N.
  const double cp = std::cos(n.phi), sp = std::sin(n.phi);
  return {r.x * cp + r.z * sp, r.y, -r.x * sp + r.z * cp};
}

Coords map_coords(const ViewFrame& view, const glm::dvec3& n) {
  const glm::dvec3 side(view.side[0], view.side[1], view.side[2]);
  const glm::dvec3 up(view.up[0], view.up[1], view.up[2]);
  const glm::dvec3 dir(view.dir[0], view.dir[1], view.dir[2]);
  Coords c;
  c.un = glm::dot(n, side);
  c.vn = glm::dot(n, up);
  const double hn = glm::dot(n, dir);
  c.ur = 2 * hn * c.un;
  c.vr = 2 * hn * c.vn;
  c.wr = 2 * hn * hn - 1;
  return c;
}

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
  const double la = glm::length(a), lb = glm::length(b);
  if (la == 0 || lb == 0) return 0;
  // atan2 of the cross and dot products: accurate for tiny angles too.
  const double rad = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
  return rad * 180.0 / 3.14159265358979323846;
}

}  // namespace tmu::deflect::ideal
