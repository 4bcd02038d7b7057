// The material keys of the deflection chain (scenes/README.md "bump and reflection"): per-pixel
// shading through shading maps, the bump map, the specular term, the environment map and the
// reflectance. Checked here so that a scene either loads completely or names its first problem.
#include <fmt/format.h>

#include <bit>

#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

constexpr int kMinMapSide = 128;   // the map coordinates' 2^-14 steps map to whole
constexpr int kMaxMapSide = 1024;  // sub-texel steps from 128 texels up (render/map_coords)

int map_side(const JsonNode& node) {
  const auto side = static_cast<int>(node.integer(kMinMapSide, kMaxMapSide));
  if (!std::has_single_bit(static_cast<unsigned>(side))) node.fail("must be 128, 256, 512 or 1024");
  return side;
}

// A map read at the texture's (u, v) must have the texture's size: a pattern without a size
// takes it.
TextureSource parse_linked_map(const JsonNode& node, const std::string& folder,
                               const Material& material) {
  TextureSource t = parse_texture(node, folder);
  if (t.kind == TextureSource::Kind::kPattern && !node.has("size")) {
    t.width = material.texture.width;
    t.height = material.texture.height;
  }
  if (t.width != material.texture.width || t.height != material.texture.height) {
    node.fail(
        fmt::format("is read at the texture's (u, v), so it needs the texture's size {}x{} "
                    "(it is {}x{})",
                    material.texture.width, material.texture.height, t.width, t.height));
  }
  if (t.kind == TextureSource::Kind::kCcc) node.fail("must be an image or a pattern");
  return t;
}

Bump parse_bump(const JsonNode& node, const std::string& folder, const Material& material) {
  node.expect_object();
  node.allow_keys({"heights", "depth"});
  Bump b;
  b.heights = parse_linked_map(node.at("heights"), folder, material);
  if (auto depth = node.find("depth")) {
    b.depth = depth->number();
    if (!(b.depth >= 0 && b.depth <= 64)) depth->fail("must be 0..64 texels");
  }
  return b;
}

Specular parse_specular(const JsonNode& node) {
  node.expect_object();
  node.allow_keys({"colour", "exponent"});
  Specular s;
  if (auto c = node.find("colour")) s.colour = c->colour3(0, 1);
  if (auto e = node.find("exponent")) {
    s.exponent = e->number();
    if (!(s.exponent >= 1 && s.exponent <= 1000)) e->fail("must be 1..1000");
  }
  return s;
}

Environment parse_environment(const JsonNode& node, const std::string& folder) {
  node.expect_object();
  node.allow_keys({"map", "size", "image"});
  Environment e;
  if (auto map = node.find("map")) {
    e.kind = map->one_of({"sphere", "cube"}) == "cube" ? Environment::Kind::kCube
                                                       : Environment::Kind::kSphere;
  }
  if (auto size = node.find("size")) e.size = map_side(*size);
  if (auto image = node.find("image")) {
    if (e.kind == Environment::Kind::kCube) image->fail("the cube map is rendered from the room");
    e.image = resolve_existing_file(*image, folder);
  }
  return e;
}

Reflectance parse_reflectance(const JsonNode& node, const std::string& folder,
                              const Material& material) {
  Reflectance r;
  if (node.json().is_number()) {
    const double k = node.number();
    if (!(k >= 0 && k <= 1)) node.fail("must be 0..1");
    r.constant = glm::dvec3(k);
  } else if (node.json().is_array()) {
    r.constant = node.colour3(0, 1);
  } else {
    node.expect_object();
    node.allow_keys({"map", "detail"});
    r.map = parse_linked_map(node.at("map"), folder, material);
    if (auto d = node.find("detail"))
      r.detail = parse_detail(*d, folder, {material.texture.width, material.texture.height});
  }
  return r;
}

}  // namespace

void parse_effects(const JsonNode& node, const std::string& folder, Material& m) {
  const bool any = node.has("shading") || node.has("bump") || node.has("specular") ||
                   node.has("environment") || node.has("reflectance");
  if (any && m.unit == Material::Unit::kLowcost) {
    node.fail(
        "shading maps, bump, specular, environment and reflectance need the TEXRAM "
        "(not unit lowcost)");
  }
  if (auto b = node.find("bump")) m.bump = parse_bump(*b, folder, m);
  if (auto s = node.find("specular")) m.specular = parse_specular(*s);
  if (auto e = node.find("environment")) m.environment = parse_environment(*e, folder);
  // A bump deflects the normal the shading maps read; a specular term lives in a shading map.
  const bool needs_maps = m.bump || m.specular;
  m.shading = needs_maps ? Material::Shading::kMaps : Material::Shading::kVertex;
  if (auto shading = node.find("shading")) {
    if (shading->one_of({"vertex", "maps"}) == "maps") {
      m.shading = Material::Shading::kMaps;
    } else if (needs_maps) {
      shading->fail("bump and specular need per-pixel shading (shading \"maps\")");
    }
  }
  if (auto size = node.find("shading_map_size")) {
    if (m.shading != Material::Shading::kMaps) size->fail("only applies to shading \"maps\"");
    m.shading_map_size = map_side(*size);
  }
  if (m.specular && m.environment) {
    node.at("specular").fail("eq. 7 adds either the environment E or the specular term I_s");
  }
  if (auto r = node.find("reflectance")) {
    if (!m.specular && !m.environment) r->fail("needs a specular term or an environment map");
    m.reflectance = parse_reflectance(*r, folder, m);
  }
}

}  // namespace tmu::host
