// The objects of a scene file and their transforms (scenes/README.md).
#include <fmt/format.h>

#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

// Tessellation limits: below them the shape is degenerate, above them a typo (a million
// segments) would quietly cost minutes.
constexpr int kMaxSegments = 1024;

glm::dvec2 positive2(const JsonNode& node) {
  const glm::dvec2 v = node.vec2();
  for (size_t i = 0; i < 2; ++i) {
    if (!(v[static_cast<int>(i)] > 0)) node[i].fail("must be > 0");
  }
  return v;
}

glm::dvec3 positive3(const JsonNode& node) {
  const glm::dvec3 v = node.vec3();
  for (size_t i = 0; i < 3; ++i) {
    if (!(v[static_cast<int>(i)] > 0)) node[i].fail("must be > 0");
  }
  return v;
}

glm::ivec2 segments(const JsonNode& node, int min_first, int min_second) {
  node.expect_array();
  if (node.size() != 2) node.fail("expected a list of 2 integers");
  return {static_cast<int>(node[0].integer(min_first, kMaxSegments)),
          static_cast<int>(node[1].integer(min_second, kMaxSegments))};
}

int material_index(const JsonNode& node, const std::vector<Material>& materials) {
  const std::string name = node.string();
  for (size_t i = 0; i < materials.size(); ++i) {
    if (materials[i].name == name) return static_cast<int>(i);
  }
  node.fail("unknown material '" + name + "'");
}

Object parse_object(const JsonNode& node, const std::vector<Material>& materials,
                    const std::string& folder) {
  node.expect_object();
  Object o;
  const std::string type =
      node.at("type").one_of({"plane", "box", "sphere", "torus", "mesh", "nurbs"});
  if (type == "nurbs") {
    parse_nurbs_object(node, o);
  } else if (type == "plane") {
    node.allow_keys({"type", "material", "transform", "uv_repeat", "size"});
    o.shape = Object::Shape::kPlane;
    if (auto size = node.find("size")) {
      const glm::dvec2 s = positive2(*size);
      o.size = {s.x, 1, s.y};
    }
  } else if (type == "box") {
    node.allow_keys({"type", "material", "transform", "uv_repeat", "size"});
    o.shape = Object::Shape::kBox;
    if (auto size = node.find("size")) o.size = positive3(*size);
  } else if (type == "sphere") {
    node.allow_keys({"type", "material", "transform", "uv_repeat", "radius", "segments"});
    o.shape = Object::Shape::kSphere;
    if (auto r = node.find("radius")) o.radius = r->positive();
    if (auto s = node.find("segments")) o.segments = segments(*s, 3, 2);
  } else if (type == "torus") {
    node.allow_keys({"type", "material", "transform", "uv_repeat", "radius", "tube", "segments"});
    o.shape = Object::Shape::kTorus;
    if (auto r = node.find("radius")) o.radius = r->positive();
    if (auto t = node.find("tube")) o.tube = t->positive();
    if (auto s = node.find("segments")) o.segments = segments(*s, 3, 3);
  } else {
    node.allow_keys({"type", "material", "transform", "uv_repeat", "file"});
    o.shape = Object::Shape::kMesh;
    o.file = resolve_existing_file(node.at("file"), folder);
  }
  if (auto uv = node.find("uv_repeat")) {
    o.uv_repeat = uv->vec2();
    for (size_t i = 0; i < 2; ++i) {
      if (o.uv_repeat[static_cast<int>(i)] == 0) (*uv)[i].fail("must not be 0");
    }
  }
  o.material = material_index(node.at("material"), materials);
  const Material& m = materials[static_cast<size_t>(o.material)];
  if (o.shape != Object::Shape::kNurbs && m.tau) {
    node.at("material")
        .fail(fmt::format(
            "material '{}' has a tau mapping (tau, order or lod), which needs a nurbs object",
            m.name));
  }
  if (auto t = node.find("transform")) o.transform = parse_transform(*t);
  return o;
}

}  // namespace

Transform parse_transform(const JsonNode& node) {
  node.allow_keys({"translate", "rotate", "scale"});
  Transform t;
  if (auto v = node.find("translate")) t.translate = v->vec3();
  if (auto v = node.find("rotate")) t.rotate_deg = v->vec3();
  if (auto v = node.find("scale")) {
    t.scale = v->vec3();
    // A zero scale flattens the object into a plane seen edge-on: every triangle degenerate.
    for (size_t i = 0; i < 3; ++i) {
      if (t.scale[static_cast<int>(i)] == 0) (*v)[i].fail("must not be 0");
    }
  }
  return t;
}

std::vector<Object> parse_objects(const JsonNode& node, const std::vector<Material>& materials,
                                  const std::string& folder) {
  std::vector<Object> objects;
  for (size_t i = 0; i < node.size(); ++i)
    objects.push_back(parse_object(node[i], materials, folder));
  return objects;
}

}  // namespace tmu::host
