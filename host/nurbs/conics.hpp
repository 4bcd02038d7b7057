// Exact rational nets of the quadric surfaces the scenes use (The NURBS Book §8.5, surfaces of
// revolution): a profile in the (radius, y) plane swept around the Y axis by the 9-point circle
// (degree 2, weights 1 at the square's edge midpoints and sqrt(2)/2 at its corners, knots
// {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}). Point (i, j) is (rho_j c_i.x, y_j, rho_j c_i.z) with
// weight w_i w_j, which makes S(s, t) = (rho(t) cos, y(t), rho(t) sin) exactly.
//
// All three have the domain [0,1] x [0,1], s runs around the Y axis from +X toward +Z, t runs
// "down" the profile (from +Y toward -Y on the outside), and dS/ds x dS/dt points outward.
#pragma once

#include "nurbs/patch.hpp"

namespace tmu::host::nurbs {

// t from the north pole (0, r, 0) to the south pole (0, -r, 0) along the half-circle net (degree
// 2, 5 points, weights 1, sqrt(2)/2, 1, sqrt(2)/2, 1, knots {0,0,0,1/2,1/2,1,1,1}): a 9 x 5 net
// whose first and last rows collapse to the poles, where dS/ds = 0.
Patch sphere(double radius);

// The tube's circle of radius `minor` centred at distance `major` from the Y axis, t starting
// at the outer equator (major + minor, 0, 0) and going down first (9 x 9 net).
Patch torus(double major, double minor);

// Around the Y axis, t linear (degree_t 1) from the top rim y = +height/2 to the bottom rim
// y = -height/2 (9 x 2 net, centred on the origin).
Patch cylinder(double radius, double height);

}  // namespace tmu::host::nurbs
