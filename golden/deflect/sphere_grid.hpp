// Golden's arithmetic on the angular grid (sphere_grid_definition.hpp: eq. 12, the nodes,
// theta's sign and magnitude): building and decoding theta, and the octant expansion.
#pragma once

#include <cstdint>

#include "deflect/sphere_grid_definition.hpp"

namespace tmu::deflect {

// Theta from a sign and a magnitude; zero is always +0.
constexpr uint32_t make_theta(const SphereGrid& g, bool negative, uint32_t mag) {
  return (uint32_t{negative && mag != 0} << g.mag_bits()) | mag;
}
constexpr bool theta_negative(const SphereGrid& g, uint32_t theta) {
  return (theta >> g.mag_bits()) & 1u;
}
constexpr uint32_t theta_mag(const SphereGrid& g, uint32_t theta) {
  return theta & (g.quarter() - 1);
}
// Theta as a signed count of steps.
constexpr int32_t theta_steps(const SphereGrid& g, uint32_t theta) {
  const auto m = static_cast<int32_t>(theta_mag(g, theta));
  return theta_negative(g, theta) ? -m : m;
}

// The octant expansion shared by the normal encoder and the spherical-to-spherical map: a
// first-octant horizontal angle l (0 .. Q steps from +z towards +x) moved to the quadrant
// of the signs of x and z:
//   x >= 0, z >= 0: l        x >= 0, z < 0: 2Q - l
//   x <  0, z <  0: 2Q + l   x <  0, z >= 0: 4Q - l      (all modulo 4Q)
constexpr uint32_t expand_phi(const SphereGrid& g, bool x_negative, bool z_negative, uint32_t l) {
  const uint32_t q2 = 2 * g.quarter();
  uint32_t p = 0;
  if (!x_negative)
    p = z_negative ? q2 - l : l;
  else
    p = z_negative ? q2 + l : 2 * q2 - l;
  return p & g.phi_mask();
}

}  // namespace tmu::deflect
