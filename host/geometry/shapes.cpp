// The built-in shapes of scenes/README.md, tessellated in object space as grids of quads
// (geometry/mesh_builder.hpp turns each triangle to face outward).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/mesh_builder.hpp"
#include "nurbs/nurbs_mesh.hpp"

namespace tmu::host {
namespace {

constexpr double kPi = std::numbers::pi;

// Facing +Y, u along +x and v along +z, so an image lies upright seen from above with -z up.
Mesh plane(const Object& o) {
  Mesh m;
  const double hx = o.size.x / 2, hz = o.size.z / 2;
  const glm::dvec3 n(0, 1, 0);
  const glm::dvec2 r = o.uv_repeat;
  const uint32_t a = add_vertex(m, {-hx, 0, -hz}, n, glm::dvec2(0, 0) * r);
  const uint32_t b = add_vertex(m, {hx, 0, -hz}, n, glm::dvec2(1, 0) * r);
  const uint32_t c = add_vertex(m, {hx, 0, hz}, n, glm::dvec2(1, 1) * r);
  const uint32_t d = add_vertex(m, {-hx, 0, hz}, n, glm::dvec2(0, 1) * r);
  add_quad(m, a, b, c, d);
  return m;
}

// Four vertices per face (normals are per face); on each face u runs to the right and v
// downward seen from outside, with +Y up on the sides (and -Z up on top, +Z up below), so an
// image appears upright and unmirrored on every face.
Mesh box(const Object& o) {
  struct Face {
    glm::dvec3 normal, right, down;
  };
  constexpr Face kFaces[] = {
      {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
      {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
  };
  Mesh m;
  const glm::dvec3 half = o.size / 2.0;
  for (const Face& f : kFaces) {
    uint32_t corner[4];
    const glm::dvec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k) {
      const glm::dvec3 p =
          (f.normal + (2 * uvs[k].x - 1) * f.right + (2 * uvs[k].y - 1) * f.down) * half;
      corner[k] = add_vertex(m, p, f.normal, uvs[k] * o.uv_repeat);
    }
    add_quad(m, corner[0], corner[1], corner[2], corner[3]);
  }
  return m;
}

// Longitude phi from -pi (the seam, at -Z) through 0 (+Z); u grows eastward (toward +X at the
// front) and v from the north pole (+Y, v = 0) to the south pole. A pole is one vertex per
// segment, at the segment's middle u, so the texture does not twist around it.
glm::dvec3 on_unit_sphere(double u, double v) {
  const double phi = 2 * kPi * u - kPi, theta = kPi * v;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

Mesh sphere(const Object& o) {
  const int around = o.segments.x, up = o.segments.y;
  Mesh m;
  // Rows 0 and `up` are the poles (around vertices each), rows between have around + 1 (seam).
  std::vector<std::vector<uint32_t>> row(static_cast<size_t>(up) + 1);
  for (int i = 0; i <= up; ++i) {
    const double v = static_cast<double>(i) / up;
    const bool pole = i == 0 || i == up;
    for (int j = 0; j <= around - (pole ? 1 : 0); ++j) {
      const double u = (j + (pole ? 0.5 : 0.0)) / around;
      glm::dvec3 n = on_unit_sphere(u, v);
      if (pole) n = {0, i == 0 ? 1 : -1, 0};
      row[static_cast<size_t>(i)].push_back(
          add_vertex(m, o.radius * n, n, glm::dvec2(u, v) * o.uv_repeat));
    }
  }
  for (size_t i = 0; i + 1 < row.size(); ++i) {
    const std::vector<uint32_t>& top = row[i];
    const std::vector<uint32_t>& bottom = row[i + 1];
    for (size_t j = 0; j < static_cast<size_t>(around); ++j) {
      if (i == 0) {
        add_triangle(m, top[j], bottom[j], bottom[j + 1]);  // the north pole
      } else if (i + 2 == row.size()) {
        add_triangle(m, top[j], top[j + 1], bottom[j]);  // the south pole
      } else {
        add_quad(m, top[j], top[j + 1], bottom[j + 1], bottom[j]);
      }
    }
  }
  return m;
}

// The ring lies in the XZ plane around +Y; u runs around the ring (same longitude as the
// sphere), v around the tube starting on the outer equator and going over the top.
Mesh torus(const Object& o) {
  const int around = o.segments.x, tube = o.segments.y;
  Mesh m;
  const auto index = [&](int j, int k) { return static_cast<uint32_t>(j * (tube + 1) + k); };
  for (int j = 0; j <= around; ++j) {
    const double u = static_cast<double>(j) / around;
    const glm::dvec3 radial = on_unit_sphere(u, 0.5);
    for (int k = 0; k <= tube; ++k) {
      const double v = static_cast<double>(k) / tube;
      const double psi = 2 * kPi * v;
      const glm::dvec3 n = std::cos(psi) * radial + std::sin(psi) * glm::dvec3(0, 1, 0);
      add_vertex(m, o.radius * radial + o.tube * n, n, glm::dvec2(u, v) * o.uv_repeat);
    }
  }
  for (int j = 0; j < around; ++j) {
    for (int k = 0; k < tube; ++k) {
      add_quad(m, index(j, k), index(j + 1, k), index(j + 1, k + 1), index(j, k + 1));
    }
  }
  return m;
}

}  // namespace

Mesh make_mesh(const Object& object) {
  switch (object.shape) {
    case Object::Shape::kPlane:
      return plane(object);
    case Object::Shape::kBox:
      return box(object);
    case Object::Shape::kSphere:
      return sphere(object);
    case Object::Shape::kTorus:
      return torus(object);
    case Object::Shape::kMesh: {
      Mesh m = load_obj(object.file);
      for (Vertex& v : m.vertices) v.uv *= object.uv_repeat;
      return m;
    }
    case Object::Shape::kNurbs:
      throw std::invalid_argument("make_mesh: a nurbs object is tessellated by make_meshes");
  }
  return {};
}

std::vector<Mesh> make_meshes(const Scene& scene, const std::vector<glm::ivec2>& texture_sizes) {
  std::vector<Mesh> meshes;
  for (const Object& o : scene.objects) {
    if (o.shape == Object::Shape::kNurbs) {
      const auto m = static_cast<size_t>(o.material);
      meshes.push_back(nurbs::tessellate(o, scene.materials[m], scene.camera, texture_sizes.at(m)));
    } else {
      meshes.push_back(make_mesh(o));
    }
  }
  return meshes;
}

}  // namespace tmu::host
