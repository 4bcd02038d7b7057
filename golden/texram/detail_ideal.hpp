// The ideal (double precision) detail-map sample of 000 §9, by the rules docs/detail.md states
// and detail.hpp implements in integers, but exactly: real coordinates, real weights, no
// rounding. It reads the sources only: the texture's and the detail map's source texels
// (source_texels.hpp, through the ideal trilinear unit of trilinear_ideal.hpp, which builds its
// own exact box pyramid) and the offset maps as given. It shares with golden only definitions
// (detail_definition.hpp, sampler_config.hpp, the containers); tests/detail_test.cpp measures
// golden against it, and tests/detail_reference_test.cpp checks it against a reference of its
// own (the regions pasted into one texture 16 times larger).
#pragma once

#include <array>
#include <cstdint>

#include "texram/detail_definition.hpp"
#include "texram/level8.hpp"
#include "texram/sampler_config.hpp"
#include "texram/source_texels.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::texram {

struct IdealDetailMap {
  IdealTexture detail;        // the detail map's exact pyramid (level l: lambda = l - 4)
  Level8 offset_u, offset_v;  // the offsets as given, one per level-0 texel of the texture
};

// Throws std::invalid_argument when the source is inconsistent (ideal_texture's reasons) or the
// offset maps differ in size.
IdealDetailMap ideal_detail_map(const SourceTexels& detail, const Level8& offset_u,
                                const Level8& offset_v);

// u, v in level-0 texels of the texture, lambda in levels (any real value; >= 0 is the ideal
// trilinear unit's sample). RGBA, 0..255 each, unrounded.
std::array<double, 4> ideal_detail_sample(const IdealTexture& texture, const SamplerConfig& config,
                                          const IdealDetailMap& map, DetailCombine combine,
                                          double u, double v, double lambda, uint32_t shade = 0);

}  // namespace tmu::texram
