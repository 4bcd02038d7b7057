// OpenImageIO's TextureSystem as an independent reference for the TEXRAM's filters: the
// border modes as its wrap modes, a texture as a MIP-mapped file it reads (its level 0, or
// our whole pyramid), and the derivative that makes its trilinear lookup blend our lambda's
// levels. Used by tests/texram_ideal_oiio_test.cpp, `texsim sweep footprint` and
// bench/texram_oiio_bench.cpp.
#pragma once

#include <OpenImageIO/texture.h>

#include <string>

#include "texram/oiio_sampler.hpp"  // make_oiio_texture, the anisotropic sampler
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::texram {

// WrapPeriodic = wrap, WrapClamp = clamp, WrapMirror = mirror, WrapBlack = border (the same
// only with a (0, 0, 0, 0) border colour).
OIIO::TextureOpt::Wrap oiio_wrap(Border border);

// Every level of `texture` written as one MIP level of a tiled float OpenEXR file, so OIIO
// filters the same texels as our models (Debian's OpenImageIO writes no MIP-mapped TIFF; float
// keeps every 8-bit value exact): golden's pyramid read back through the bank layout as
// `config` reads its texels, or the ideal's exact levels. Throws InputError naming `path` when
// OpenImageIO fails.
void write_oiio_mip_texture(const std::string& path, const TexramTexture& texture,
                            const SamplerConfig& config);
void write_oiio_mip_texture(const std::string& path, const IdealTexture& texture,
                            const SamplerConfig& config);

// The derivative (normalized texture units per pixel, the same for d/dx and d/dy) that makes
// OIIO's MipModeTrilinear lookup use our lambda's levels and blend, for a square texture of
// side `width` with `top` as its last level. OIIO blends linearly in filter width: with the
// filter width f (texels) at the first level m where f <= 1, it blends levels m - 1 and m by
// 2f - 1; our lambda = (m - 1) + t blends them by t, so this gives f = (1 + t) / 2 at level m.
// Square textures only: OIIO uses min(width, height) per level.
float oiio_trilinear_derivative(double lambda, int top, int width);

}  // namespace tmu::texram
