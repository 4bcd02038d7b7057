// The angular grid of the deflection unit (001 §4.1, §7.2), as data: a direction on the unit
// sphere as a horizontal angle phi and a vertical angle theta, eq. 12:
//   x = cos(theta) sin(phi),  y = sin(theta),  z = cos(phi) cos(theta),
// i.e. phi measured about the vertical (y) axis from +z towards +x, theta the elevation.
//
// A grid of 2^A x 2^(A-1) patches (A = phi_bits: 9 gives the paper's 512 x 256) has the step
// delta = 2 pi / 2^A in both angles. The angles are the grid's nodes:
// - phi: A bits, phi = p delta, modulo 2^A (wraps across 0 / 2 pi by itself);
// - theta: sign and magnitude (the paper: "the first bit in theta denotes the sign"),
//   theta = +-m delta with m = 0 .. Q - 1 where Q = 2^(A-2) nodes span a quarter turn; the
//   poles (m = Q) saturate to Q - 1, at most one step away. The units write zero as +0 (an
//   input -0 reads as zero).
// Nodes rather than patch centres because the unit adds angles (phi_D - theta_N, then
// + phi_N): sums of nodes are nodes, and the undeflected bump texel (0, 0) is exact. Negating
// theta flips its sign bit; negating phi is the two's complement modulo 2^A.
//
// Definitions only (the grid's sizes and step, the port fields): golden (sphere_grid.hpp) and
// the ideal model (deflect_ideal.hpp) each decode the angles by their own code, and
// tests/deflect_test.cpp checks that the two agree.
#pragma once

#include <cstdint>
#include <numbers>

namespace tmu::deflect {

struct SphereGrid {
  int phi_bits = 9;  // A, 6..12

  constexpr uint32_t phi_count() const { return 1u << phi_bits; }      // 4 Q
  constexpr uint32_t quarter() const { return 1u << (phi_bits - 2); }  // Q
  constexpr int mag_bits() const { return phi_bits - 2; }              // theta magnitude bits
  constexpr int theta_bits() const { return phi_bits - 1; }            // sign + magnitude
  constexpr uint32_t phi_mask() const { return phi_count() - 1; }
  constexpr double step() const { return 2.0 * std::numbers::pi / phi_count(); }  // radians
  friend constexpr bool operator==(const SphereGrid&, const SphereGrid&) = default;
};

// A direction on the grid: raw port values.
struct SphereAngle {
  uint32_t phi = 0;    // A bits
  uint32_t theta = 0;  // sign at bit A-2, magnitude below
  friend constexpr bool operator==(const SphereAngle&, const SphereAngle&) = default;
};

}  // namespace tmu::deflect
