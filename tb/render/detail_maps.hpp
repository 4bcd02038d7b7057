// The detail maps of a scene's materials (000 §9, docs/detail.md), built by the host from the
// scene's "detail" keys: the detail mipmap in its configuration, and the two offset maps (tiled,
// or the luminance of two images) at the size of the map they detail.
#pragma once

#include <glm/glm.hpp>
#include <memory>

#include "scene/scene.hpp"
#include "texram/detail.hpp"
#include "texram/detail_ideal.hpp"

namespace tmu::render {

// The detail map of `detail` for a map of `size` level-0 texels. Throws InputError for an
// unreadable image and std::invalid_argument for a map make_detail_map refuses.
std::shared_ptr<const texram::DetailMap> build_detail_map(const host::Detail& detail,
                                                          glm::ivec2 size);

// The same detail map for the ideal renderer: the detail map's source texels (its exact pyramid)
// and the offsets as given.
std::shared_ptr<const texram::IdealDetailMap> build_ideal_detail_map(const host::Detail& detail,
                                                                     glm::ivec2 size);

// The tiled offsets: texel (x, y)'s region at (16 x mod 256, 16 y mod 256).
texram::Level8 tiled_offsets(glm::ivec2 size, bool v);

}  // namespace tmu::render
