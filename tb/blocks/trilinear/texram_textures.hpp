// The textures the TEXRAM sampling path's environments name: built from a setup (a pattern
// or random bytes of its kind and size, drawn from its content seed), or given (an image file,
// imported in the setup's kind; a ready texture, a scene's). Built once per setup and shared
// by golden, the memory of every timed level and the copies of the block the engines keep.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "blocks/trilinear/texram_setup.hpp"
#include "common/image.hpp"
#include "texram/texture.hpp"

namespace tmu::tb {

class TexramTextures {
 public:
  // `block` names the block in errors; `paint` (optional) changes every texture built from a
  // pattern or random bytes, never given content (footprint paints a white region), and
  // `painted` says so in content().
  using Paint = std::function<void(texram::TexramTexture&)>;
  explicit TexramTextures(std::string block, Paint paint = {}, std::string painted = "");
  // Every setup's texture is this image in the setup's kind (sides powers of two up to 1024).
  // Throws InputError for an unreadable image or one of other sides.
  void give_image(const std::string& path);
  // Every setup's texture is this one (its kind and size).
  void give_texture(std::shared_ptr<const texram::TexramTexture> texture, std::string name);

  // The setup adjusted to the given content: pattern kGiven with its size (and a given
  // texture's kind); unchanged without one.
  TexramSetup fit(TexramSetup setup) const;
  // The texture of a setup. Throws std::invalid_argument naming the block when the setup does
  // not fit the given content (another size or kind), or names no content (a given pattern
  // without one).
  std::shared_ptr<const texram::TexramTexture> texture_of(const TexramSetup& setup) const;
  // What the setup's texture holds, for a report ("smooth field", the file, the scene's name).
  std::string content(const TexramSetup& setup) const;

 private:
  std::string block_;
  Paint paint_;
  std::string painted_;
  std::string given_name_;
  std::shared_ptr<const ImageRgb8> image_;
  std::shared_ptr<const texram::TexramTexture> texture_;
  // The last few textures built, newest last (a random run returns to none of the old ones).
  mutable std::mutex mutex_;
  mutable std::vector<std::pair<TexramSetup, std::shared_ptr<const texram::TexramTexture>>> cache_;
};

}  // namespace tmu::tb
