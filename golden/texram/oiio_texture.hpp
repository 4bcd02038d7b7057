// OpenImageIO's TextureSystem as an independent reference for the TEXRAM's filters: the
// border modes as its wrap modes, and a texture's level 0 as a MIP-mapped file it reads.
// Used by tests/texram_ideal_oiio_test.cpp and `texsim sweep footprint`.
#pragma once

#include <OpenImageIO/texture.h>

#include <string>

#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"

namespace tmu::texram {

// WrapPeriodic = wrap, WrapClamp = clamp, WrapMirror = mirror, WrapBlack = border (the same
// only with a (0, 0, 0, 0) border colour).
OIIO::TextureOpt::Wrap oiio_wrap(Border border);

// Level 0 of `texture`, as `config` reads its texels (RGBA, the CLUT applied), turned into a
// tiled, MIP-mapped float OpenEXR file by OIIO::ImageBufAlgo::make_texture (OIIO builds the
// pyramid itself, with a box filter; float keeps every 8-bit value exact). Throws InputError
// naming `path` when OpenImageIO fails.
void make_oiio_texture(const std::string& path, const TexramTexture& texture,
                       const SamplerConfig& config);

}  // namespace tmu::texram
