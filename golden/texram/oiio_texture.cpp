#include "texram/oiio_texture.hpp"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <utility>
#include <vector>

#include "common/error.hpp"

namespace tmu::texram {

namespace {

// `levels` levels, level l w(l) x h(l) with RGBA float pixels pixels(l), as one MIP-mapped file.
template <class Size, class Pixels>
void write_mip_levels(const std::string& path, int levels, const Size& size, const Pixels& pixels) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw InputError(path, "", "cannot create: " + OIIO::geterror());
  for (int l = 0; l < levels; ++l) {
    const auto [w, h] = size(l);
    OIIO::ImageSpec spec(static_cast<int>(w), static_cast<int>(h), 4, OIIO::TypeDesc::FLOAT);
    spec.tile_width = spec.tile_height = 64;
    spec.attribute("openexr:levelmode", 1);  // MIPMAP_LEVELS
    spec.attribute("textureformat", "Plain Texture");
    const std::vector<float> rgba = pixels(l);
    if (!out->open(path, spec,
                   l == 0 ? OIIO::ImageOutput::Create : OIIO::ImageOutput::AppendMIPLevel) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, rgba.data())) {
      throw InputError(path, "", "writing MIP level " + std::to_string(l) + ": " + out->geterror());
    }
  }
  if (!out->close()) throw InputError(path, "", "close: " + out->geterror());
}

}  // namespace

void write_oiio_mip_texture(const std::string& path, const TexramTexture& texture,
                            const SamplerConfig& config) {
  const Geometry& g = texture.geometry;
  write_mip_levels(
      path, g.levels(), [&](int l) { return std::pair(g.texel_width(l), g.texel_height(l)); },
      [&](int l) { return level_rgba(texture, config, l); });
}

void write_oiio_mip_texture(const std::string& path, const IdealTexture& texture,
                            const SamplerConfig& config) {
  const auto size = [&](int l) { return std::pair(texture.width_of(l), texture.height_of(l)); };
  write_mip_levels(path, texture.levels(), size, [&](int l) {
    const auto [w, h] = size(l);
    std::vector<float> rgba;
    for (uint32_t y = 0; y < h; ++y) {
      for (uint32_t x = 0; x < w; ++x) {
        for (double c : ideal_texel(texture, config, l, x, y))
          rgba.push_back(static_cast<float>(c / 255.0));
      }
    }
    return rgba;
  });
}

float oiio_trilinear_derivative(double lambda, int top, int width) {
  if (lambda <= 0) return 0.5f / static_cast<float>(width);  // finer than level 0: magnification
  if (lambda >= top) return 4.0f;                            // coarser than the last level
  const double m = std::ceil(lambda);                        // second level
  const double t = lambda - (m - 1);                         // blend, (0, 1]
  return static_cast<float>((1 + t) * std::ldexp(1.0, static_cast<int>(m) - 1) / width);
}

}  // namespace tmu::texram
