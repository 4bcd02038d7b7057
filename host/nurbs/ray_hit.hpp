// Where the ray through a pixel meets a NURBS object, found on the surface itself rather than on
// its tessellation: the exact parameter coordinates a pixel shows and their screen derivatives.
// `texsim sweep nurbs` uses it for its reference frame (every fragment of the finely tessellated
// reference moved onto the true surface), so that the thresholds' error is measured against the
// surface, not against another tessellation.
//
// Method: Newton's method on F(s, t, lambda) = S(s, t) - (o + lambda d) = 0, in object space
// (the ray mapped by the inverse modelling transform, which keeps it a line), from the
// tessellation's (s, t). Jacobian [dS/ds, dS/dt, -d]. Each step evaluates the patch whose knot
// domain holds the current (s, t) (several patches of one object have disjoint domains that
// tile the object's parameter rectangle), so a step may cross into a neighbour. The screen
// derivatives follow from the same Jacobian at the solution: differentiating
// S(s(x), t(x)) = o + lambda(x) d(x) gives J (ds/dx, dt/dx, dlambda/dx) = lambda dd/dx.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "scene/scene.hpp"

namespace tmu::host::nurbs {

struct PixelHit {
  glm::dvec2 pc{0};             // the object's normalised (s, t) (nurbs_mesh.hpp's pc_rectangle)
  glm::dvec2 d_dx{0}, d_dy{0};  // d(s, t)/dx and d(s, t)/dy, per pixel (y down)
  glm::dvec3 position{0};       // the point, world space
  glm::dvec3 normal{0};         // the surface's unit normal there (dS/ds x dS/dt), world space
};

// The point of `object` (a NURBS object) seen through the screen point (x, y) (pixel centres at
// i + 0.5), starting Newton from the normalised parameter coordinates `guess`. nullopt when
// Newton does not converge within 30 steps to a residual below 1e-9 of the object's size, or
// the Jacobian is singular there (the ray grazes the surface: a silhouette, a collapsed pole),
// or the point leaves the parameter rectangle, or lies behind the eye.
std::optional<PixelHit> hit_through_pixel(const Object& object, const Camera& camera, double x,
                                          double y, glm::dvec2 guess);

}  // namespace tmu::host::nurbs
