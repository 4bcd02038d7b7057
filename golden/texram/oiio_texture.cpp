#include "texram/oiio_texture.hpp"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <vector>

#include "common/error.hpp"

namespace tmu::texram {

void write_oiio_mip_texture(const std::string& path, const TexramTexture& texture,
                            const SamplerConfig& config) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw InputError(path, "", "cannot create: " + OIIO::geterror());
  for (int l = 0; l < texture.geometry.levels(); ++l) {
    const int w = static_cast<int>(texture.geometry.texel_width(l)),
              h = static_cast<int>(texture.geometry.texel_height(l));
    OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::FLOAT);
    spec.tile_width = spec.tile_height = 64;
    spec.attribute("openexr:levelmode", 1);  // MIPMAP_LEVELS
    spec.attribute("textureformat", "Plain Texture");
    const std::vector<float> pixels = level_rgba(texture, config, l);
    if (!out->open(path, spec,
                   l == 0 ? OIIO::ImageOutput::Create : OIIO::ImageOutput::AppendMIPLevel) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) {
      throw InputError(path, "", "writing MIP level " + std::to_string(l) + ": " + out->geterror());
    }
  }
  if (!out->close()) throw InputError(path, "", "close: " + out->geterror());
}

float oiio_trilinear_derivative(double lambda, int top, int width) {
  if (lambda <= 0) return 0.5f / static_cast<float>(width);  // finer than level 0: magnification
  if (lambda >= top) return 4.0f;                            // coarser than the last level
  const double m = std::ceil(lambda);                        // second level
  const double t = lambda - (m - 1);                         // blend, (0, 1]
  return static_cast<float>((1 + t) * std::ldexp(1.0, static_cast<int>(m) - 1) / width);
}

}  // namespace tmu::texram
