#include "texram/oiio_texture.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <vector>

#include "common/error.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::texram {

OIIO::TextureOpt::Wrap oiio_wrap(Border border) {
  switch (border) {
    case Border::kWrap:
      return OIIO::TextureOpt::WrapPeriodic;
    case Border::kClamp:
      return OIIO::TextureOpt::WrapClamp;
    case Border::kMirror:
      return OIIO::TextureOpt::WrapMirror;
    case Border::kBorder:
      return OIIO::TextureOpt::WrapBlack;
  }
  return OIIO::TextureOpt::WrapDefault;
}

void make_oiio_texture(const std::string& path, const TexramTexture& texture,
                       const SamplerConfig& config) {
  const int w = static_cast<int>(texture.geometry.texel_width(0)),
            h = static_cast<int>(texture.geometry.texel_height(0));
  std::vector<float> pixels;
  pixels.reserve(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint32_t texel =
          texel_rgba(texture, config, 0, static_cast<uint32_t>(x), static_cast<uint32_t>(y));
      for (int c = 0; c < 4; ++c) pixels.push_back(static_cast<float>(channel(texel, c)) / 255.0f);
    }
  }
  const OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::FLOAT);
  const OIIO::ImageBuf level0(spec, pixels.data());
  OIIO::ImageSpec cfg;
  cfg.format = OIIO::TypeDesc::FLOAT;
  cfg.tile_width = cfg.tile_height = 64;
  cfg.tile_depth = 1;
  cfg.attribute("maketx:filtername", "box");
  cfg.attribute("maketx:compute_average", 0);
  if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, level0, path, cfg)) {
    throw InputError(path, "", "make_texture failed: " + OIIO::geterror());
  }
}

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
    std::vector<float> pixels;
    pixels.reserve(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const uint32_t texel =
            texel_rgba(texture, config, l, static_cast<uint32_t>(x), static_cast<uint32_t>(y));
        for (int c = 0; c < 4; ++c)
          pixels.push_back(static_cast<float>(channel(texel, c)) / 255.0f);
      }
    }
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
