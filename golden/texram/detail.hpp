// Golden model of detail maps (000 §9): below level 0 (lambda < 0) a texture continues into a
// detail mipmap of four more levels, lambda = -1 .. -4, reached through two detail offset maps.
// This file is the specification a later chip model and RTL match; docs/detail.md gives the
// reasons for every choice and the measured accuracy.
//
// Data (DetailMap):
// - the detail map: an ordinary TEXRAM texture (any texel kind, sides powers of two 16..256)
//   with its own box pyramid; its level l stands for lambda = l - 4 (levels 0..3 are used);
// - two offset maps of 8-bit entries at the texture's level-0 size: texel (x, y)'s region is the
//   16 x 16 texels of the detail map's level 0 starting at (offset_u(x, y), offset_v(x, y)),
//   wrapping at the detail map's sides (so offsets 240..255 of a 256-wide map wrap to 0..15).
//
// A sample (sample_detail), with the request's raw ports u, v (SQ16.8 level-0 texels) and lambda
// (SQ6.8), at the trilinear unit's widths S, W, L (SamplerConfig::widths):
// - lambda >= 0, or no detail map: texram::sample, bit for bit and access for access.
// - lambda < 0 (the patent's "whenever a negative lambda is received"); lq = lambda floored to
//   L fraction bits (as the trilinear unit does):
//   1. the offset maps, each one nearest-texel read of level 0 at (u, v) under the texture's
//      border modes: (ou, ov). Border mode outside the texture there is no texel, so no region:
//      the offset accesses read nothing and the sample is the texture's at lambda 0 (step 3 with
//      eq. 5), no detail;
//   2. the detail map, trilinear, border mode wrap, at u_d = ou + 16 frac(u), v_d = ov +
//      16 frac(v) (raw: (ou << 8) + ((u & 255) << 4), exact), lambda_d = lq + 4 for lq <= -1,
//      lambda_d = 3 for -1 < lq < 0; below -4 the trilinear unit magnifies level 0 (lambda_d
//      <= 0): the detail colour D, RGBA8888. Taps at a region's edge read the detail map's own
//      neighbours (the next region of the map), not the neighbouring level-0 texel's region.
//   3. the texture, texram::sample at (u, v) with lambda 0 and combine "one" (its level 0 under
//      its own filter and borders): T, when the combine is modulate or wt != 0 below.
//   wt, the W-bit weight of the texture's level 0 against the detail's level -1: 0 for lq <= -1,
//   else the fraction lq + 1 (L bits) widened or truncated to W bits.
//   Per channel, with one rounding (half up) each:
//     replace   C = ((2^W - wt) D + wt T + 2^(W-1)) >> W
//     modulate  RGB: P = min(T D, 255 * 128) (7 fraction bits: T D / 128 saturated at 255),
//                    C = ((2^W - wt) P + wt (T << 7) + 2^(W+6)) >> (W + 7);  A: C = T's alpha
//   then eq. 5 (texram::combine) with the request's shade, as the trilinear unit applies it.
//
// Accesses (DetailAccess, in order): offset u, offset v, detail, texture (when read); each is a
// SamplePlan of the map it reads (planes() accesses of the eight banks, none when nothing is
// read). Luminance texture and detail map: 3 (lambda <= -1, replace) or 4 accesses.
#pragma once

#include <cstdint>
#include <vector>

#include "texram/detail_definition.hpp"
#include "texram/level8.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram {

struct DetailMap {
  TexramTexture detail;    // the detail mipmap: level l is lambda = l - 4
  TexramTexture offset_u;  // luminance, level 0 read only (its levels above hold zeros)
  TexramTexture offset_v;
};

// A detail map from its texture and the two offset maps (same size, powers of two up to 1024).
// Throws std::invalid_argument naming the reason (a detail side outside 16..256 or not a power
// of two, offset maps of different sizes).
DetailMap make_detail_map(TexramTexture detail, const Level8& offset_u, const Level8& offset_v);

struct DetailConfig {
  DetailCombine combine = DetailCombine::kReplace;
};

// Which map an access reads.
enum class DetailMapId : uint8_t { kOffsetU, kOffsetV, kDetail, kTexture };

struct DetailAccess {
  DetailMapId map = DetailMapId::kTexture;
  SamplePlan plan;  // its banks and addresses (plane p reads address + p, planes times)
};

// Accesses of the eight banks the record makes (plan.planes per access that reads a bank).
int bank_accesses(const std::vector<DetailAccess>& accesses);

// The lambda part of a detail sample (the rules above).
struct DetailLevels {
  bool detail = false;   // lambda < 0: the detail path
  int32_t lambda_d = 0;  // the detail map's lambda, SQ6.8
  uint32_t wt = 0;       // W-bit weight of the texture's level 0 (0 for lambda <= -1)
};
DetailLevels detail_levels(const Widths& widths, int32_t lambda);

// The sampler configurations of steps 1 and 2, derived from the texture's.
SamplerConfig offset_sampler(const SamplerConfig& texture_config);
SamplerConfig detail_sampler(const DetailMap& map, const SamplerConfig& texture_config);

// Step 1: the region (ou, ov) of the level-0 texel nearest (u, v); appends two accesses.
struct DetailRegion {
  bool outside = false;     // border mode, outside the texture: no region
  uint32_t ou = 0, ov = 0;  // DetailOffset: the region's first texel in the detail map's level 0
};
DetailRegion read_region(const DetailMap& map, const SamplerConfig& texture_config,
                         const Request& request, std::vector<DetailAccess>* accesses);

// Step 2's request: (u_d, v_d) in the detail map's level-0 texels, lambda_d.
Request detail_request(const DetailRegion& region, const Request& request, int32_t lambda_d);

// The combine rules on RGBA8888 D and T with the W-bit weight wt of T (the rules above).
uint32_t replace_colour(uint32_t d, uint32_t t, uint32_t wt, int weight_bits);
uint32_t modulate_colour(uint32_t d, uint32_t t, uint32_t wt, int weight_bits);

// The whole sample, RGBA8888. `map` may be null (no detail map). `accesses` (optional) receives
// the accesses in order. Throws std::invalid_argument when the map does not fit the texture
// (offset maps not at its level-0 size, or a sphere-addressed texture).
uint32_t sample_detail(const TexramTexture& texture, const SamplerConfig& config,
                       const DetailMap* map, const DetailConfig& detail_config,
                       const Request& request, std::vector<DetailAccess>* accesses = nullptr);

}  // namespace tmu::texram
