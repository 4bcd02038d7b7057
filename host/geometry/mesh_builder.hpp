// Building meshes from vertices and triangles. Each triangle is turned so that its geometric
// normal agrees with its vertices' normals, which makes every surface counter-clockwise seen
// from outside by construction rather than by getting each winding right by hand.
#pragma once

#include <utility>

#include "geometry/mesh.hpp"

namespace tmu::host {

// Appends triangle (a, b, c), turned to face the way its vertex normals point; a degenerate
// triangle (a sphere's pole) is dropped.
inline void add_triangle(Mesh& m, uint32_t a, uint32_t b, uint32_t c) {
  const Vertex& va = m.vertices[a];
  const Vertex& vb = m.vertices[b];
  const Vertex& vc = m.vertices[c];
  const glm::dvec3 g = glm::cross(vb.position - va.position, vc.position - va.position);
  if (glm::dot(g, g) == 0) return;
  if (glm::dot(g, va.normal + vb.normal + vc.normal) < 0) std::swap(b, c);
  m.triangles.push_back({a, b, c});
}

inline void add_quad(Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  add_triangle(m, a, b, c);
  add_triangle(m, a, c, d);
}

inline uint32_t add_vertex(Mesh& m, const Vertex& v) {
  m.vertices.push_back(v);
  return static_cast<uint32_t>(m.vertices.size() - 1);
}

inline uint32_t add_vertex(Mesh& m, const glm::dvec3& p, const glm::dvec3& n,
                           const glm::dvec2& uv) {
  return add_vertex(m, Vertex{p, n, uv});
}

}  // namespace tmu::host
