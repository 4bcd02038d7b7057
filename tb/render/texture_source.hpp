// The level-0 image of a scene's texture source: an image file or a pattern.
#pragma once

#include "common/image.hpp"
#include "scene/scene.hpp"

namespace tmu::render {

// Throws InputError for an unreadable image (a .ccc source is not an image: the caller reads it).
ImageRgb8 source_image(const host::TextureSource& source);

}  // namespace tmu::render
