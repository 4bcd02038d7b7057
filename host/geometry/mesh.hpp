// Triangle meshes of the scene's objects, in object space.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tmu::host {

struct Vertex {
  glm::dvec3 position{0};
  glm::dvec3 normal{0, 1, 0};  // unit, object space
  glm::dvec2 uv{0};            // texture coordinates, 1 = one texture across (times uv_repeat)
  // A fixed level of detail for the fragments of its triangles (004 claim 12, per patch; the
  // first vertex of a triangle decides); NaN: lambda per pixel from the derivatives.
  double lod = std::numeric_limits<double>::quiet_NaN();
  // The colour interpolated across its triangles (004 claims 17, 18: the texture colour, or
  // the composed one, at the vertex), 0..255 per channel; unused otherwise.
  glm::dvec4 colour{0};
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

// The object's mesh (plane, box, sphere, torus, or its OBJ file). Throws InputError naming the
// OBJ file and line on a malformed file; a nurbs object needs make_meshes.
Mesh make_mesh(const Object& object);

// Every object's mesh, scene.objects[i] in [i]: nurbs objects tessellated for the scene's
// camera with their material's level-0 texture size texture_sizes[m] (nurbs/nurbs_mesh.hpp).
std::vector<Mesh> make_meshes(const Scene& scene, const std::vector<glm::ivec2>& texture_sizes);

// An OBJ file: v, vt, vn, f (3 or more vertices, fanned; v/vt/vn, v//vn, v/vt and negative
// indices); other statements are ignored. Missing normals become face normals. vt's v is
// flipped (1 - v): OBJ puts v = 0 at the bottom of the image, the texture unit at the top.
Mesh load_obj(const std::string& path);

}  // namespace tmu::host
