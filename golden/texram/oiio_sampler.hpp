// OpenImageIO's TextureSystem as a reference filter, behind an interface without OIIO types
// (as common/image_file.hpp is for image files, so that texsim reaches it through its
// OpenImageIO plugin, common/oiio_plugin.hpp): a TEXRAM texture made into a texture file,
// looked up anisotropically. Used by `texsim sweep footprint`; oiio_texture.hpp adds the helpers
// that take OIIO types. oiio_sampler.cpp, which implements the OIIO side, uses nothing else of
// golden/: the plugin is built from it alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram {

// Level `level` of `texture` as `config` reads its texels (the CLUT applied): RGBA floats
// 0..1, row-major (float keeps every 8-bit value exact).
inline std::vector<float> level_rgba(const TexramTexture& texture, const SamplerConfig& config,
                                     int level) {
  const auto w = texture.geometry.texel_width(level), h = texture.geometry.texel_height(level);
  std::vector<float> pixels;
  pixels.reserve(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const uint32_t texel = texel_rgba(texture, config, level, x, y);
      for (int c = 0; c < 4; ++c) pixels.push_back(static_cast<float>(channel(texel, c)) / 255.0f);
    }
  }
  return pixels;
}

// RGBA float pixels (width x height, row-major) made into a tiled, MIP-mapped float OpenEXR
// file by OIIO::ImageBufAlgo::make_texture (OIIO builds the pyramid itself, with a box filter).
// Throws InputError naming `path` when OpenImageIO fails.
void make_oiio_texture(const std::string& path, int width, int height, std::vector<float> rgba);

// Level 0 of `texture`, as `config` reads its texels, made into such a file.
inline void make_oiio_texture(const std::string& path, const TexramTexture& texture,
                              const SamplerConfig& config) {
  make_oiio_texture(path, static_cast<int>(texture.geometry.texel_width(0)),
                    static_cast<int>(texture.geometry.texel_height(0)),
                    level_rgba(texture, config, 0));
}

// A texture file and the border modes it is looked up with (oiio_wrap in oiio_texture.hpp).
struct OiioTextureFile {
  std::string path;
  Border border_u = Border::kWrap, border_v = Border::kWrap;
};

// A private OIIO::TextureSystem over texture files: anisotropic (MipModeAniso), bilinear within
// a level, each file with its wrap modes; one thread's Perthread record, so one thread only.
class OiioAnisoSampler {
 public:
  virtual ~OiioAnisoSampler() = default;
  // File `index` at (s, t) with the derivatives d/dx, d/dy, all in normalized texture units:
  // RGBA 0..1 into rgba. False on failure; error() says why.
  virtual bool lookup(size_t index, float s, float t, float dsdx, float dtdx, float dsdy,
                      float dtdy, float rgba[4]) = 0;
  virtual std::string error() = 0;
  // OIIO's statistics text (getstats(1, false)).
  virtual std::string statistics() = 0;
};

// At most `max_probes` probes per lookup (TextureOpt::anisotropic).
std::unique_ptr<OiioAnisoSampler> make_oiio_aniso_sampler(const std::vector<OiioTextureFile>& files,
                                                          int max_probes);

}  // namespace tmu::texram
