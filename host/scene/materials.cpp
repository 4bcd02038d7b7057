// The materials of a scene file: where the texels come from and how the TEXRAM samples them
// (scenes/README.md). Texture files are checked here (exist, readable, sides in range) so that
// a scene either loads completely or names its first problem.
#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <exception>

#include "ccc/ccc_texture.hpp"
#include "common/error.hpp"
#include "common/image_file.hpp"
#include "formats/formats.hpp"
#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

// The TEXRAM holds power-of-two sides up to 2^10 (000 §2, formats.def MaxMipLog2); the CCC
// low-cost unit reads level 0 only and takes any side a TexSize holds.
constexpr int kMaxTexramSide = 1 << formats::kMaxMipLog2;

bool texram_side(int s) {
  return s >= 1 && s <= kMaxTexramSide && std::has_single_bit(unsigned(s));
}

// RGBA colours in scenes are 0..1; the ports carry RGBA8888 with round(255 x), ties to even.
uint32_t to_rgba8888(const glm::dvec4& c) {
  uint32_t packed = 0;
  for (int i = 0; i < 4; ++i) {
    const auto byte = static_cast<uint32_t>(formats::Channel::from_double(255.0 * c[i]).raw());
    packed = (packed << 8) | byte;
  }
  return packed;
}

glm::ivec2 image_size(const JsonNode& node, const std::string& path) {
  std::string why;
  const auto in = open_image_file(path, &why);
  if (!in) node.fail("cannot read the image " + path + ": " + why);
  return {in->width(), in->height()};
}

glm::ivec2 ccc_size(const JsonNode& node, const std::string& path) {
  try {
    const ccc::Texture t = ccc::read_ccc(path);
    return {static_cast<int>(t.width), static_cast<int>(t.height)};
  } catch (const InputError& e) {
    node.fail(fmt::format("bad CCC file {}: {}{}", path, e.field().empty() ? "" : e.field() + ": ",
                          e.reason()));
  }
}

glm::ivec2 parse_size(const JsonNode& node) {
  node.expect_array();
  if (node.size() != 2) node.fail("expected a list of 2 integers (width, height)");
  return {static_cast<int>(node[0].integer(1, formats::kMaxTexSize)),
          static_cast<int>(node[1].integer(1, formats::kMaxTexSize))};
}

std::vector<glm::dvec3> parse_two_colours(const JsonNode& node) {
  node.expect_array();
  if (node.size() != 2) node.fail("expected a list of 2 colours");
  return {node[0].colour3(0, 1), node[1].colour3(0, 1)};
}

}  // namespace

TextureSource parse_texture(const JsonNode& node, const std::string& folder) {
  node.expect_object();
  const int forms = int(node.has("image")) + int(node.has("ccc")) + int(node.has("pattern"));
  if (forms == 0) node.fail("needs one of the keys image, ccc, pattern");
  if (forms > 1) node.fail("has more than one of the keys image, ccc, pattern");
  TextureSource t;
  if (auto image = node.find("image")) {
    node.allow_keys({"image"});
    t.kind = TextureSource::Kind::kImage;
    t.path = resolve_existing_file(*image, folder);
    const glm::ivec2 size = image_size(*image, t.path);
    t.width = size.x;
    t.height = size.y;
    return t;
  }
  if (auto ccc = node.find("ccc")) {
    node.allow_keys({"ccc"});
    t.kind = TextureSource::Kind::kCcc;
    t.path = resolve_existing_file(*ccc, folder);
    const glm::ivec2 size = ccc_size(*ccc, t.path);
    t.width = size.x;
    t.height = size.y;
    return t;
  }
  t.kind = TextureSource::Kind::kPattern;
  const JsonNode pattern = node.at("pattern");
  t.pattern = pattern.one_of({"checker", "text", "gradient", "noise", "smooth", "default"});
  if (t.pattern == "checker") {
    node.allow_keys({"pattern", "size", "cell", "colours"});
    if (auto cell = node.find("cell")) t.cell = static_cast<int>(cell->integer(1, 4096));
    t.colours = {glm::dvec3(0), glm::dvec3(1)};  // as `texsim pattern checker`
  } else if (t.pattern == "text") {
    node.allow_keys({"pattern", "size", "text", "colours"});
    const JsonNode text = node.at("text");
    t.text = text.string();
    if (t.text.empty()) text.fail("must not be empty");
    t.colours = {glm::dvec3(0), glm::dvec3(1)};  // black ink on white paper
  } else {
    node.allow_keys({"pattern", "size", "seed"});
    if (auto seed = node.find("seed")) t.seed = static_cast<uint32_t>(seed->integer(0, 0xFFFFFFFF));
  }
  if (auto colours = node.find("colours")) t.colours = parse_two_colours(*colours);
  if (auto size = node.find("size")) {
    const glm::ivec2 s = parse_size(*size);
    t.width = s.x;
    t.height = s.y;
  }
  return t;
}

namespace {

texram::Border parse_border_mode(const JsonNode& node) {
  node.one_of({"wrap", "clamp", "border", "mirror"});
  return *texram::parse_border(node.string());
}

// "footprint": {"max_probes": 1|2|4|8|16, "q": "heights"|"sides"}.
footprint::Config parse_footprint(const JsonNode& node) {
  node.expect_object();
  node.allow_keys({"max_probes", "q"});
  footprint::Config c;
  if (auto n = node.find("max_probes")) {
    const int64_t probes = n->integer(1, int64_t{1} << formats::kMaxProbeLog2);
    if (!std::has_single_bit(static_cast<uint64_t>(probes))) n->fail("must be 1, 2, 4, 8 or 16");
    c.log2_max_probes = std::countr_zero(static_cast<uint64_t>(probes));
  }
  if (auto q = node.find("q")) c.q_rule = *footprint::parse_q_rule(q->one_of({"heights", "sides"}));
  return c;
}

// A video material: what the chip's video path can do with it. Only the chip samples a video
// map (its buffers are in the chip's memory), the video port sets the configuration, and the
// video's own mipmap generator builds the pyramid.
void check_video_material(const JsonNode& node, Material& m) {
  const texram::TexelKind kind =
      m.video->planes == 1 ? texram::TexelKind::kLuminance : texram::TexelKind::kTrueColour;
  if (auto config = node.find("config"); config && m.sampler.kind != kind) {
    config->fail(fmt::format("a video of {} plane{} is held as {}", m.video->planes,
                             m.video->planes == 1 ? "" : "s",
                             m.video->planes == 1 ? "luminance" : "rgba"));
  }
  m.sampler.kind = kind;
  const JsonNode video = node.at("video");
  if (node.has("mipmaps"))
    node.at("mipmaps").fail("a video's pyramid is made by its own mipmap generator (000 §12)");
  if (m.unit == Material::Unit::kLowcost)
    video.fail("a video map is the TEXRAM's (not unit lowcost)");
  if (m.order == Material::Order::kTexture || m.order == Material::Order::kComposed)
    video.fail("orders texture and composed sample at the vertices, not through the chip");
}

Material parse_material(const JsonNode& node, const std::string& name, const std::string& folder) {
  node.expect_object();
  Material m;
  m.name = name;
  if (auto p = node.find("procedural")) {
    // No texture: the material unit computes the colour; eq. 5 with the vertex shade or not.
    node.allow_keys({"procedural", "combine"});
    parse_procedural(*p, m);
    m.sampler.combine = texram::Combine::kShade;
    if (auto combine = node.find("combine")) {
      if (combine->one_of({"one", "shade"}) == "one") m.sampler.combine = texram::Combine::kOne;
    }
    m.texture.width = m.texture.height = 1;
    return m;
  }
  node.allow_keys({"texture",     "config",
                   "channel",     "filter",
                   "border",      "border_colour",
                   "combine",     "constant",
                   "unit",        "mipmaps",
                   "footprint",   "detail",
                   "shading",     "shading_map_size",
                   "bump",        "specular",
                   "environment", "reflectance",
                   "procedural",  "tau",
                   "order",       "lod",
                   "video"});
  if (node.has("video") && node.has("texture"))
    node.at("video").fail("a material has a texture or a video, not both");
  if (auto video = node.find("video")) {
    m.video = parse_video(*video, folder);
    // The video's frames are the texture: its size for the rasterizer's uv scale, never loaded
    // (render/video_feed writes the chip's memory).
    m.texture.pattern = "video";
    m.texture.width = m.video->width;
    m.texture.height = m.video->height;
  } else {
    m.texture = parse_texture(node.at("texture"), folder);
  }
  const bool ccc_file = m.texture.kind == TextureSource::Kind::kCcc;

  texram::SamplerConfig& s = m.sampler;
  s.kind = ccc_file ? texram::TexelKind::kCcc : texram::TexelKind::kTrueColour;
  s.combine = texram::Combine::kShade;
  s.border_rgba = to_rgba8888({0, 0, 0, 1});
  s.constant_rgba = to_rgba8888({1, 1, 1, 1});
  if (auto config = node.find("config")) {
    config->one_of({"luminance", "index", "rgba", "single", "ccc"});
    s.kind = *texram::parse_texel_kind(config->string());
    if (ccc_file && s.kind != texram::TexelKind::kCcc) {
      config->fail("a .ccc texture has the configuration ccc");
    }
  }
  if (auto channel = node.find("channel")) {
    const std::string c = channel->one_of({"r", "g", "b", "a"});
    if (s.kind != texram::TexelKind::kSingle) channel->fail("only applies to config single");
    s.single_channel = c == "r" ? 0 : c == "g" ? 1 : c == "b" ? 2 : 3;
  }
  if (auto filter = node.find("filter")) {
    filter->one_of({"nearest", "bilinear", "trilinear"});
    s.filter = *texram::parse_filter(filter->string());
  }
  if (auto border = node.find("border")) {
    if (border->json().is_object()) {
      border->allow_keys({"u", "v"});
      if (auto u = border->find("u")) s.border_u = parse_border_mode(*u);
      if (auto v = border->find("v")) s.border_v = parse_border_mode(*v);
    } else if (border->json().is_string()) {
      s.border_u = s.border_v = parse_border_mode(*border);
    } else {
      border->fail("expected a border mode or an object {\"u\": mode, \"v\": mode}");
    }
  }
  if (auto c = node.find("border_colour")) s.border_rgba = to_rgba8888(c->colour4(0, 1));
  if (auto combine = node.find("combine")) {
    combine->one_of({"one", "constant", "shade"});
    s.combine = *texram::parse_combine(combine->string());
  }
  if (auto c = node.find("constant")) s.constant_rgba = to_rgba8888(c->colour4(0, 1));

  if (auto unit = node.find("unit")) {
    if (unit->one_of({"trilinear", "lowcost"}) == "lowcost") {
      if (s.kind != texram::TexelKind::kCcc) unit->fail("the lowcost unit needs config ccc");
      m.unit = Material::Unit::kLowcost;
    }
  }
  if (auto mipmaps = node.find("mipmaps")) {
    if (mipmaps->one_of({"host", "mipgen"}) == "mipgen") {
      // The generator of 000 §12 averages 8-bit planes: indices and CCC blocks are not.
      if (s.kind == texram::TexelKind::kIndex || s.kind == texram::TexelKind::kCcc) {
        mipmaps->fail("the mipmap generator builds luminance, single and rgba textures only");
      }
      m.mipmaps = Material::Mipmaps::kMipgen;
    }
  }

  if (auto f = node.find("footprint")) {
    if (m.unit == Material::Unit::kLowcost) f->fail("footprint assembly drives the trilinear unit");
    m.footprint = parse_footprint(*f);
  }

  parse_effects(node, folder, m);
  parse_tau(node, m);
  if (auto d = node.find("detail")) {
    if (m.unit == Material::Unit::kLowcost)
      d->fail("a detail map is the TEXRAM's (not unit lowcost)");
    m.detail = parse_detail(*d, folder, {m.texture.width, m.texture.height});
  }
  if (m.has_detail()) {  // only the chip samples detail maps: the material must go to one
    const JsonNode d = node.has("detail") ? node.at("detail") : node.at("reflectance").at("detail");
    if (m.mipmaps == Material::Mipmaps::kMipgen)
      d.fail(
          "the chip samples detail maps, and the mipmap generator does not write a chip's "
          "memory yet (mipmaps host)");
    if (m.order == Material::Order::kTexture || m.order == Material::Order::kComposed)
      d.fail("orders texture and composed sample at the vertices, not through the chip");
  }

  if (m.video) {
    check_video_material(node, m);
    return m;
  }
  // Sides: what the unit that samples the texture can hold.
  const JsonNode texture = node.at("texture");
  const JsonNode where = m.texture.kind == TextureSource::Kind::kImage ? texture.at("image")
                         : ccc_file                                    ? texture.at("ccc")
                         : texture.has("size")                         ? texture.at("size")
                                                                       : texture;
  // Images always (scenes/README.md); a .ccc file or a pattern may be any TexSize for the
  // low-cost unit.
  const bool lowcost =
      m.unit == Material::Unit::kLowcost && m.texture.kind != TextureSource::Kind::kImage;
  if (!lowcost && !(texram_side(m.texture.width) && texram_side(m.texture.height))) {
    where.fail(
        fmt::format("the TEXRAM needs sides that are powers of two up to {} (texture is {}x{})",
                    kMaxTexramSide, m.texture.width, m.texture.height));
  }
  if (lowcost &&
      (m.texture.width > formats::kMaxTexSize || m.texture.height > formats::kMaxTexSize)) {
    where.fail(fmt::format("sides up to {} (texture is {}x{})", formats::kMaxTexSize,
                           m.texture.width, m.texture.height));
  }
  return m;
}

}  // namespace

std::vector<Material> parse_materials(const JsonNode& node, const std::string& folder) {
  node.expect_object();
  // Fragments carry the material as a MaterialId.
  const size_t max_materials = size_t{1} << formats::kMaterialId.width();
  if (node.json().size() > max_materials) {
    node.fail(fmt::format("at most {} materials (a fragment's MaterialId has {} bits)",
                          max_materials, formats::kMaterialId.width()));
  }
  std::vector<Material> materials;
  for (const auto& [name, value] : node.json().items()) {
    const JsonNode m(value, join_path(node.path(), name), node.file());
    if (name.empty()) m.fail("a material needs a non-empty name");
    materials.push_back(parse_material(m, name, folder));
  }
  return materials;
}

}  // namespace tmu::host
