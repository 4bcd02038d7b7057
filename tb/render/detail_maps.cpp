#include "render/detail_maps.hpp"

#include "render/texture_source.hpp"
#include "texram/detail_definition.hpp"
#include "texram/texture.hpp"

namespace tmu::render {

texram::Level8 tiled_offsets(glm::ivec2 size, bool v) {
  texram::Level8 o(static_cast<uint32_t>(size.x), static_cast<uint32_t>(size.y));
  for (uint32_t y = 0; y < o.height; ++y) {
    for (uint32_t x = 0; x < o.width; ++x)  // 8 bits: mod 256
      o.at(x, y) = static_cast<uint8_t>(texram::kDetailRegionSide * (v ? y : x));
  }
  return o;
}

namespace {

struct Offsets {
  texram::Level8 u, v;
};

Offsets offsets_of(const host::Detail& detail, glm::ivec2 size) {
  if (detail.offsets == host::Detail::Offsets::kTiled)
    return {tiled_offsets(size, false), tiled_offsets(size, true)};
  return {texram::plane_of(source_image(detail.offset_u), texram::luma),
          texram::plane_of(source_image(detail.offset_v), texram::luma)};
}

}  // namespace

std::shared_ptr<const texram::IdealDetailMap> build_ideal_detail_map(const host::Detail& detail,
                                                                     glm::ivec2 size) {
  const texram::TexramTexture map = texram::import_image(source_image(detail.map), detail.kind);
  const Offsets o = offsets_of(detail, size);
  return std::make_shared<const texram::IdealDetailMap>(
      texram::ideal_detail_map(map.source, o.u, o.v));
}

std::shared_ptr<const texram::DetailMap> build_detail_map(const host::Detail& detail,
                                                          glm::ivec2 size) {
  texram::TexramTexture map = texram::import_image(source_image(detail.map), detail.kind);
  const Offsets o = offsets_of(detail, size);
  return std::make_shared<const texram::DetailMap>(
      texram::make_detail_map(std::move(map), o.u, o.v));
}

}  // namespace tmu::render
