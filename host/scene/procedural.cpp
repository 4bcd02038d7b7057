// A procedural material's keys (scenes/README.md "procedural"): the material, the solid
// coordinates' scale, the colour stops and the parameters that material reads. A parameter
// that another material reads is an error here, as is a value its register cannot hold.
#include <fmt/format.h>

#include <bit>
#include <cmath>

#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

using perlin::MaterialKind;

constexpr std::string_view kKinds[] = {"marble", "wood", "brick", "fog", "cloud", "fire"};

// Each material's own keys besides "material" and "scale".
std::vector<std::string_view> own_keys(MaterialKind k) {
  switch (k) {
    case MaterialKind::kMarble:
      return {"colours", "turbulence", "stripes"};
    case MaterialKind::kWood:
      return {"colours", "turbulence", "rings", "slope"};
    case MaterialKind::kBrick:
      return {"colours", "mortar_colours", "turbulence", "brick", "mortar"};
    case MaterialKind::kFog:
      return {"gain"};
    case MaterialKind::kCloud:
      return {"gain", "cutoff"};
    case MaterialKind::kFire:
      return {"colours", "turbulence", "offset"};
  }
  return {};
}

// The stops' defaults: what each material looks like without "colours".
std::vector<perlin::ColourStop> default_colours(MaterialKind k) {
  switch (k) {
    case MaterialKind::kMarble:
      return {{0, {0.92, 0.91, 0.88}},
              {0.45, {0.85, 0.84, 0.82}},
              {0.5, {0.35, 0.35, 0.4}},
              {0.55, {0.8, 0.8, 0.78}},
              {1, {0.92, 0.91, 0.88}}};
    case MaterialKind::kWood:
      return {{0, {0.72, 0.5, 0.28}}, {0.7, {0.62, 0.4, 0.2}}, {1, {0.42, 0.25, 0.12}}};
    case MaterialKind::kBrick:
      return {{0, {0.62, 0.22, 0.15}}, {0.5, {0.7, 0.3, 0.2}}, {1, {0.55, 0.2, 0.14}}};
    case MaterialKind::kFire:
      return {{0, {0, 0, 0}},
              {0.35, {0.6, 0.05, 0}},
              {0.6, {1, 0.45, 0}},
              {0.85, {1, 0.85, 0.2}},
              {1, {1, 1, 0.9}}};
    default:
      return {};
  }
}

std::vector<perlin::ColourStop> parse_stops(const JsonNode& node) {
  node.expect_array();
  if (node.size() == 0) node.fail("expected at least one stop [position, [r, g, b]]");
  std::vector<perlin::ColourStop> stops;
  for (size_t i = 0; i < node.size(); ++i) {
    const JsonNode stop = node[i];
    stop.expect_array();
    if (stop.size() != 2) stop.fail("expected [position, [r, g, b]]");
    perlin::ColourStop s;
    s.position = stop[0].number();
    if (!(s.position >= 0 && s.position <= 1)) stop[0].fail("must be 0..1");
    if (!stops.empty() && s.position < stops.back().position)
      stop[0].fail("stops must be in increasing position");
    const glm::dvec3 c = stop[1].colour3(0, 1);
    s.rgb = {c.r, c.g, c.b};
    stops.push_back(s);
  }
  return stops;
}

// A number within what its register holds.
double register_value(const JsonNode& node, double lo, double hi) {
  const double v = node.number();
  if (!(v >= lo && v <= hi)) node.fail(fmt::format("must be {}..{}", lo, hi));
  return v;
}

// A brick period: a power of two in solid units the raw grid holds (2^-11 .. 2^8).
glm::dvec2 parse_period(const JsonNode& node) {
  node.expect_array();
  if (node.size() != 2) node.fail("expected [width, height]");
  glm::dvec2 p;
  for (int i = 0; i < 2; ++i) {
    const JsonNode e = node[static_cast<size_t>(i)];
    p[i] = e.number();
    int exp = 0;
    const double m = std::frexp(p[i], &exp);
    if (!(p[i] > 0) || m != 0.5 || exp - 1 < -11 || exp - 1 > 8)
      e.fail("must be a power of two from 2^-11 to 2^8 (the row is a shift, no divider)");
  }
  return p;
}

}  // namespace

void parse_procedural(const JsonNode& node, Material& m) {
  node.expect_object();
  Procedural p;
  const JsonNode kind = node.at("material");
  const std::string name = kind.one_of({"marble", "wood", "brick", "fog", "cloud", "fire"});
  for (size_t i = 0; i < std::size(kKinds); ++i) {
    if (kKinds[i] == name) p.kind = static_cast<MaterialKind>(i);
  }
  const std::vector<std::string_view> own = own_keys(p.kind);
  for (const auto& [key, value] : node.json().items()) {
    if (key == "material" || key == "scale") continue;
    if (std::find(own.begin(), own.end(), key) == own.end()) {
      node.at(key).fail(fmt::format("not a key of the {} material", name));
    }
  }
  if (auto s = node.find("scale")) {
    m.solid_scale = s->number();
    if (!(m.solid_scale > 0 && m.solid_scale <= 1024)) s->fail("must be above 0, at most 1024");
  }
  p.colours = default_colours(p.kind);
  p.mortar_colours = {{0, {0.55, 0.55, 0.52}}, {1, {0.7, 0.7, 0.66}}};
  if (auto c = node.find("colours")) p.colours = parse_stops(*c);
  if (auto c = node.find("mortar_colours")) p.mortar_colours = parse_stops(*c);
  // UQ8.8 and SQ8.8 registers (materials.hpp).
  constexpr double kU = 65535 / 256.0, kS = 32767 / 256.0;
  if (auto v = node.find("turbulence")) p.turbulence = register_value(*v, 0, kU);
  if (auto v = node.find("stripes")) p.stripes = register_value(*v, 0, kU);
  if (auto v = node.find("rings")) p.rings = register_value(*v, 0, kU);
  if (auto v = node.find("slope")) p.slope = register_value(*v, -128, kS);
  if (auto v = node.find("offset")) p.offset = register_value(*v, -128, kS);
  if (auto v = node.find("gain")) p.gain = register_value(*v, 0, kU);
  if (auto v = node.find("cutoff")) p.cutoff = register_value(*v, -2, 32767 / 16384.0);
  if (auto v = node.find("brick")) p.brick = parse_period(*v);
  if (auto v = node.find("mortar")) {
    v->expect_array();
    if (v->size() != 2) v->fail("expected [width, height]");
    for (int i = 0; i < 2; ++i) {
      const JsonNode e = (*v)[static_cast<size_t>(i)];
      p.mortar[i] = e.number();
      if (!(p.mortar[i] >= 0 && p.mortar[i] < p.brick[i] / 2))
        e.fail(fmt::format("must be 0 up to half the brick period ({})", p.brick[i] / 2));
    }
  }
  for (int i = 0; i < 2 && p.kind == MaterialKind::kBrick; ++i) {
    if (p.mortar[i] >= p.brick[i] / 2) {
      node.at(node.has("mortar") ? "mortar" : "brick")
          .fail(
              fmt::format("mortar {} leaves no brick in a period of {}", p.mortar[i], p.brick[i]));
    }
  }
  m.procedural = p;
}

}  // namespace tmu::host
