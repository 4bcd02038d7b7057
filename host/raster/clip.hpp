// Sutherland-Hodgman clipping (002 §3.1.1, Fig. 3.5) of a triangle against the six planes of
// the view volume in homogeneous clip space, glm's right-handed zero-to-one depth convention:
// -w <= x <= w, -w <= y <= w, 0 <= z <= w. Clipping at z >= 0 (the near plane, w >= near > 0)
// first removes everything behind the eye, so the later planes and the perspective divide only
// ever see w > 0.
#pragma once

#include <array>
#include <glm/glm.hpp>

namespace tmu::host {

// A convex polygon: a triangle cut by six planes has at most 3 + 6 vertices; the room beyond
// is for a numerically non-convex sliver, whose vertex signs may change more than twice.
struct ClipPolygon {
  static constexpr int kCapacity = 24;
  std::array<glm::dvec4, kCapacity> v;
  int count = 0;
};

// The part of triangle (a, b, c) inside the view volume, in the same vertex order (so the
// same orientation); count < 3 when nothing is left. An edge's intersection with a plane is
// always computed from its inside end toward its outside end, so two triangles sharing an edge
// get bit-identical new vertices on it (no cracks between their clipped parts).
ClipPolygon clip_triangle(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c);

}  // namespace tmu::host
