// The "detail" key of a texture or reflectance map (scenes/README.md "detail", docs/detail.md):
// the detail map, where each level-0 texel's region lies in it, and how its colour combines with
// the texel. Checked here: sides, offset maps of the textured map's size, the closed vocabulary.
#include <fmt/format.h>

#include <bit>

#include "formats/formats.hpp"
#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

// A detail map's sides: 16 (one region) to 256 (what 8-bit offsets reach), powers of two.
constexpr int kMinDetailSide = 16;
constexpr int kMaxDetailSide = 1 << formats::kMaxDetailLog2;

bool detail_side(int s) {
  return s >= kMinDetailSide && s <= kMaxDetailSide && std::has_single_bit(unsigned(s));
}

// The node that names a source's size: the image path, else the size key, else the source.
JsonNode size_node(const JsonNode& source) {
  if (source.has("image")) return source.at("image");
  if (source.has("size")) return source.at("size");
  return source;
}

// An offset map: an image or pattern whose luminance (0..255) is the offset, of `size`; a
// pattern without a size takes it.
TextureSource parse_offset_map(const JsonNode& node, const std::string& folder, glm::ivec2 size) {
  TextureSource t = parse_texture(node, folder);
  if (t.kind == TextureSource::Kind::kCcc) node.fail("must be an image or a pattern");
  if (t.kind == TextureSource::Kind::kPattern && !node.has("size")) {
    t.width = size.x;
    t.height = size.y;
  }
  if (t.width != size.x || t.height != size.y) {
    size_node(node).fail(fmt::format(
        "an offset map has one entry per level-0 texel of the map it details: {}x{} (it is {}x{})",
        size.x, size.y, t.width, t.height));
  }
  return t;
}

}  // namespace

Detail parse_detail(const JsonNode& node, const std::string& folder, glm::ivec2 texture_size) {
  node.expect_object();
  node.allow_keys({"map", "offsets", "combine", "config"});
  Detail d;
  const JsonNode map = node.at("map");
  d.map = parse_texture(map, folder);
  if (d.map.kind == TextureSource::Kind::kCcc) map.fail("must be an image or a pattern");
  if (d.map.kind == TextureSource::Kind::kPattern && !map.has("size")) {
    d.map.width = d.map.height = 64;  // four regions a side
  }
  if (!detail_side(d.map.width) || !detail_side(d.map.height)) {
    size_node(map).fail(fmt::format(
        "a detail map's sides are powers of two from {} (one region) to {} (what 8-bit offsets "
        "reach); it is {}x{}",
        kMinDetailSide, kMaxDetailSide, d.map.width, d.map.height));
  }
  if (auto config = node.find("config")) {
    d.kind = config->one_of({"luminance", "rgba"}) == "rgba" ? texram::TexelKind::kTrueColour
                                                             : texram::TexelKind::kLuminance;
  }
  if (auto combine = node.find("combine"))
    d.modulate = combine->one_of({"modulate", "replace"}) == "modulate";
  if (auto offsets = node.find("offsets")) {
    if (offsets->json().is_string()) {
      offsets->one_of({"tiled"});
    } else {
      offsets->expect_object();
      offsets->allow_keys({"u", "v"});
      d.offsets = Detail::Offsets::kImages;
      d.offset_u = parse_offset_map(offsets->at("u"), folder, texture_size);
      d.offset_v = parse_offset_map(offsets->at("v"), folder, texture_size);
    }
  }
  return d;
}

}  // namespace tmu::host
