// The ideal (double precision) trilinear unit of 000 §6: exact coordinates, lambda and
// weights, no rounding, computed from the texture's source texels (source_texels.hpp) by its
// own code: its own exact box pyramid (mipmap_ideal.hpp), texel addressing, border operators
// and texel decoding. It shares with golden only definitions: the source's containers, the
// sampler's configuration (sampler_config.hpp: enums, registers, the RGBA8888 packing) and
// the CCC block word's layout (written out in trilinear_ideal.cpp); docs/texram.md lists them.
// It measures what golden's widths and pyramid cost, and is itself cross-checked against
// OpenImageIO's TextureSystem (tests/texram_ideal_oiio_test.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "texram/mipmap_ideal.hpp"
#include "texram/sampler_config.hpp"
#include "texram/source_texels.hpp"

namespace tmu::texram {

// A texture's levels as the ideal reads them: per byte plane, every level, each texel the
// exact box mean of level 0 (box_levels sources) or the byte the source gives.
struct IdealTexture {
  TexelKind kind = TexelKind::kLuminance;
  uint32_t width = 0, height = 0;  // level 0, in texels
  bool block_grid = false;         // CCC: planes at block resolution
  std::vector<std::vector<LevelD>> planes;
  std::array<uint32_t, 256> clut{};
  int levels() const { return planes.empty() ? 0 : static_cast<int>(planes[0].size()); }
  // Level l's sides in texels (a side halves down to 1).
  uint32_t width_of(int level) const { return std::max(width >> level, 1u); }
  uint32_t height_of(int level) const { return std::max(height >> level, 1u); }
};

// Throws std::invalid_argument when the source is inconsistent (no planes, level sizes off, box
// levels of indices or CCC blocks, which have no mean).
IdealTexture ideal_texture(const SourceTexels& source);

// The RGBA colour (0..255 each) of texel (x, y) inside `level`, as `config` reads it.
std::array<double, 4> ideal_texel(const IdealTexture& texture, const SamplerConfig& config,
                                  int level, uint32_t x, uint32_t y);

// u, v in texels of level 0 (centres at i + 0.5), lambda in levels. Returns RGBA, 0..255 each.
std::array<double, 4> ideal_sample(const IdealTexture& texture, const SamplerConfig& config,
                                   double u, double v, double lambda, uint32_t shade = 0);

}  // namespace tmu::texram
