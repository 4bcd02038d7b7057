// The ideal (double precision) trilinear unit: the same levels, border operators, texels and
// combine as the golden model, with exact coordinates, lambda and weights and no rounding.
// It measures what the golden model's widths cost, and is itself cross-checked against
// OpenImageIO's TextureSystem (tests/texram_ideal_oiio_test.cpp).
#pragma once

#include <array>
#include <cstdint>

#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"

namespace tmu::texram {

// u, v in texels of level 0 (centres at i + 0.5), lambda in levels. Returns RGBA, 0..255 each.
std::array<double, 4> ideal_sample(const TexramTexture& texture, const SamplerConfig& config,
                                   double u, double v, double lambda, uint32_t shade = 0);

// The RGBA8888 colour of texel (x, y) of `level` (coordinates inside the level).
uint32_t texel_rgba(const TexramTexture& texture, const SamplerConfig& config, int level,
                    uint32_t x, uint32_t y);

}  // namespace tmu::texram
