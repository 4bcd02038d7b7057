// The camera and the lights of a scene file (scenes/README.md).
#include <cmath>

#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

// Largest side the PixelCoord format (12 bits) addresses.
constexpr int kMaxResolution = 4096;

// Whether glm::normalize(v), as the renderer calls it, gives a unit vector. It divides by the
// root of the sum of squares, which overflows for components beyond about 1e154 (zeros or
// NaN) and loses its precision or underflows to 0 below about 1e-154 (a wrong length or NaN).
bool normalizes(const glm::dvec3& v) {
  const glm::dvec3 n = glm::normalize(v);
  return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) &&
         std::abs(glm::length(n) - 1) < 1e-9;
}

constexpr const char* kNoDirection =
    "is too short or too long to normalize (lengths of about 1e-150..1e150 work)";

}  // namespace

Camera parse_camera(const JsonNode& node) {
  node.allow_keys({"position", "target", "up", "fov", "resolution", "near", "far"});
  Camera c;
  c.position = node.at("position").vec3();
  const JsonNode target = node.at("target");
  c.target = target.vec3();
  const JsonNode up = node.at("up");
  c.up = up.vec3();
  const glm::dvec3 view = c.target - c.position;
  if (view == glm::dvec3(0)) target.fail("equals the camera position: no view direction");
  if (!normalizes(view)) {
    target.fail(
        "is too near to or too far from the camera position for a view direction (distances of "
        "about 1e-150..1e150 work)");
  }
  if (c.up == glm::dvec3(0)) up.fail("must not be the zero vector");
  if (!normalizes(c.up)) up.fail(kNoDirection);
  // lookAt needs an up direction with a component across the view direction, and normalizes
  // the cross product of the two.
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-9) {
    up.fail("is parallel to the view direction (target - position)");
  }
  if (!normalizes(glm::cross(glm::normalize(view), c.up))) up.fail(kNoDirection);
  const JsonNode fov = node.at("fov");
  c.fov_deg = fov.number();
  if (!(c.fov_deg > 0 && c.fov_deg < 180)) fov.fail("must be in (0, 180) degrees");

  const JsonNode res = node.at("resolution");
  res.expect_array();
  if (res.size() != 2) res.fail("expected a list of 2 integers (width, height)");
  c.width = static_cast<int>(res[0].integer(1, kMaxResolution));
  c.height = static_cast<int>(res[1].integer(1, kMaxResolution));

  if (auto n = node.find("near")) {
    c.near = n->number();
    if (!(c.near > 0)) n->fail("must be > 0");
  }
  if (auto f = node.find("far")) {
    c.far = f->number();
    if (!(c.far > c.near)) f->fail("must be greater than near");
  } else if (!(c.far > c.near)) {
    node.at("near").fail("must be less than far (default 1000)");
  }
  return c;
}

std::vector<Light> parse_lights(const JsonNode& node) {
  std::vector<Light> lights;
  for (size_t i = 0; i < node.size(); ++i) {
    const JsonNode l = node[i];
    l.expect_object();
    Light light;
    const std::string type = l.at("type").one_of({"ambient", "directional", "point"});
    if (type == "ambient") {
      l.allow_keys({"type", "colour"});
      light.kind = Light::Kind::kAmbient;
    } else if (type == "directional") {
      l.allow_keys({"type", "colour", "direction"});
      light.kind = Light::Kind::kDirectional;
      const JsonNode dir = l.at("direction");
      light.vector = dir.vec3();
      if (light.vector == glm::dvec3(0)) dir.fail("must not be the zero vector");
      if (!normalizes(light.vector)) dir.fail(kNoDirection);
    } else {
      l.allow_keys({"type", "colour", "position"});
      light.kind = Light::Kind::kPoint;
      light.vector = l.at("position").vec3();
    }
    light.colour = l.at("colour").colour3(0, -1);
    lights.push_back(light);
  }
  return lights;
}

}  // namespace tmu::host
