#include "blocks/trilinear/texram_textures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "common/error.hpp"
#include "common/test_patterns.hpp"
#include "formats/formats.hpp"

namespace tmu::tb {
namespace {

// How many textures the cache keeps: a random run draws a new environment every few thousand
// items and never returns to an old one; golden and the memory ask for the same one in turn.
constexpr size_t kCached = 4;

texram::Pyramid8 random_pyramid(std::mt19937_64& rng, uint32_t w, uint32_t h) {
  texram::Pyramid8 p;
  const int levels = std::max(std::countr_zero(w), std::countr_zero(h)) + 1;
  for (int l = 0; l < levels; ++l) {
    texram::Level8 level(std::max(w >> l, 1u), std::max(h >> l, 1u));
    for (uint8_t& t : level.texels) t = static_cast<uint8_t>(rng() >> 56);
    p.push_back(std::move(level));
  }
  return p;
}

// Random bytes everywhere: every level independent, a random CLUT (random alpha too).
texram::TexramTexture random_texture(texram::TexelKind kind, int log2_w, int log2_h,
                                     uint64_t seed) {
  std::mt19937_64 rng(seed);
  const uint32_t w = 1u << log2_w, h = 1u << log2_h;
  if (kind == texram::TexelKind::kCcc) {
    ccc::Clut clut{};
    for (Rgb8& c : clut) c = unpack_rgb(static_cast<uint32_t>(rng()));
    std::vector<ccc::Texture> levels;
    for (int l = 0; l <= std::max(log2_w, log2_h); ++l) {
      ccc::Texture t;
      t.width = std::max(w >> l, 1u);
      t.height = std::max(h >> l, 1u);
      t.clut = clut;
      t.blocks.resize(size_t{t.blocks_wide()} * t.blocks_high());
      for (uint32_t& b : t.blocks) b = static_cast<uint32_t>(rng());
      levels.push_back(std::move(t));
    }
    return texram::texture_from_ccc(levels);
  }
  std::vector<texram::Pyramid8> planes;
  for (int p = 0; p < (four_planes(kind) ? formats::kPlanes : 1); ++p) {
    planes.push_back(random_pyramid(rng, w, h));
  }
  texram::Clut32 clut{};
  for (uint32_t& c : clut) c = static_cast<uint32_t>(rng());
  return texram::texture_from_planes(kind, planes, clut);
}

ImageRgb8 pattern_image(TexturePattern pattern, int w, int h, uint32_t seed) {
  switch (pattern) {
    case TexturePattern::kGradient:
      return patterns::gradient(w, h);
    case TexturePattern::kChecker:
      return patterns::checker(w, h, std::max(1, std::min(w, h) / 4), {250, 20, 30}, {10, 40, 220});
    case TexturePattern::kNoise:
      return patterns::noise(w, h, seed);
    default:
      return patterns::smooth_field(w, h, seed);
  }
}

// Whether two setups name the same texture: the fields a texture depends on.
bool same_texture(const TexramSetup& a, const TexramSetup& b) {
  const bool single = a.config.kind == texram::TexelKind::kSingle;
  return a.config.kind == b.config.kind &&
         (!single || a.config.single_channel == b.config.single_channel) && a.log2_w == b.log2_w &&
         a.log2_h == b.log2_h && a.pattern == b.pattern && a.content == b.content;
}

std::string size_text(int log2_w, int log2_h) {
  return fmt::format("{} x {}", 1 << log2_w, 1 << log2_h);
}

}  // namespace

TexramTextures::TexramTextures(std::string block, Paint paint, std::string painted)
    : block_(std::move(block)), paint_(std::move(paint)), painted_(std::move(painted)) {}

void TexramTextures::give_image(const std::string& path) {
  const ImageRgb8 image = read_image(path);
  for (const int side : {image.width, image.height}) {
    if (side < 1 || side > (1 << formats::kMaxMipLog2) || !std::has_single_bit(unsigned(side))) {
      throw InputError(path, "size",
                       fmt::format("{} x {}: the sides must be powers of two up to {}", image.width,
                                   image.height, 1 << formats::kMaxMipLog2));
    }
  }
  image_ = std::make_shared<const ImageRgb8>(image);
  given_name_ = path;
}

void TexramTextures::give_texture(std::shared_ptr<const texram::TexramTexture> texture,
                                  std::string name) {
  texture_ = std::move(texture);
  given_name_ = std::move(name);
}

TexramSetup TexramTextures::fit(TexramSetup s) const {
  if (texture_) {
    s.config.kind = texture_->kind;
    s.log2_w = texture_->geometry.log2_width();
    s.log2_h = texture_->geometry.log2_height();
  } else if (image_) {
    s.log2_w = std::countr_zero(unsigned(image_->width));
    s.log2_h = std::countr_zero(unsigned(image_->height));
  } else {
    return s;
  }
  s.pattern = TexturePattern::kGiven;
  s.content = 0;
  return s;
}

std::shared_ptr<const texram::TexramTexture> TexramTextures::texture_of(
    const TexramSetup& s) const {
  const bool given = texture_ || image_;
  if (given != (s.pattern == TexturePattern::kGiven)) {
    throw std::invalid_argument(fmt::format(
        "{}: a configuration of a {} texture, but the memory holds {}", block_, name(s.pattern),
        given ? "the given one (" + given_name_ + ")" : "no given one"));
  }
  if (texture_) {
    const texram::Geometry& g = texture_->geometry;
    if (s.config.kind != texture_->kind || s.log2_w != g.log2_width() ||
        s.log2_h != g.log2_height()) {
      throw std::invalid_argument(fmt::format(
          "{}: a configuration of a {} {} texture, but the given one ({}) is {} {}", block_,
          texram::name(s.config.kind), size_text(s.log2_w, s.log2_h), given_name_,
          texram::name(texture_->kind), size_text(g.log2_width(), g.log2_height())));
    }
    return texture_;
  }
  if (image_ && (s.log2_w != std::countr_zero(unsigned(image_->width)) ||
                 s.log2_h != std::countr_zero(unsigned(image_->height)))) {
    throw std::invalid_argument(
        fmt::format("{}: a configuration of a {} texture, but the image {} is {} x {}", block_,
                    size_text(s.log2_w, s.log2_h), given_name_, image_->width, image_->height));
  }
  std::lock_guard lock(mutex_);
  for (const auto& [setup, texture] : cache_) {
    if (same_texture(setup, s)) return texture;
  }
  texram::TexramTexture t;
  const texram::TexelKind kind = s.config.kind;
  if (image_) {
    t = texram::import_image(*image_, kind, s.config.single_channel);
  } else if (s.pattern == TexturePattern::kRandom) {
    t = random_texture(kind, s.log2_w, s.log2_h, s.content);
  } else {
    t = texram::import_image(pattern_image(s.pattern, 1 << s.log2_w, 1 << s.log2_h, s.content),
                             kind, s.config.single_channel);
  }
  if (paint_ && !image_) paint_(t);
  auto texture = std::make_shared<const texram::TexramTexture>(std::move(t));
  if (cache_.size() == kCached) cache_.erase(cache_.begin());
  cache_.emplace_back(s, texture);
  return texture;
}

std::string TexramTextures::content(const TexramSetup& s) const {
  if (s.pattern == TexturePattern::kGiven) return given_name_;
  const std::string what =
      s.pattern == TexturePattern::kRandom ? fmt::format("random bytes of seed {}", s.content)
      : s.pattern == TexturePattern::kGradient || s.pattern == TexturePattern::kChecker
          ? std::string(name(s.pattern))
          : fmt::format("{} of seed {}", name(s.pattern), s.content);
  return what + painted_;
}

}  // namespace tmu::tb
