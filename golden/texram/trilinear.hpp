// Golden model of the TEXRAM's trilinear unit (000 §2, §5, §6): address generation with the
// border operators, one access of the eight banks per byte plane, texel conversion (luminance,
// index through the CLUT, true colour, single component, CCC decode), the trilinear blend, and
// the colour combine of eq. 5. This file is the specification the hls and rtl models match.
//
// Arithmetic, with Widths {S sub-texel, W weight, L lod-fraction} bits (each 1..8):
// - Addressing (texel_request): texel coordinates pass; a sphere map's (uN, vN) become texels.
// - lambda (SQ6.8) keeps its top L fraction bits (floor). top = levels - 1.
//   trilinear: lambda <= 0 -> level 0 with weight 0 for the next level (magnification);
//              lambda >= top -> level top, weight 0; else levels floor(lambda) and the next,
//              the level weight = the lambda fraction as W bits.
//   nearest, bilinear: the one level d = floor(lambda + 1/2) clamped to 0..top.
// - A coordinate at level l: c = floor(u * 2^S / 2^l) (S fraction bits, SQ16.8 u).
//   bilinear taps: s = c - 1/2; x0 = floor(s), x1 = x0 + 1, weight of x1 = frac(s) as W bits
//   (truncated when S > W). nearest: x = floor(c).
// - Border per axis on the texel coordinate at level l of size n: wrap x mod n; clamp to
//   0..n-1; mirror (period 2n); border: outside 0..n-1 the tap is the border colour.
// - Weights of a pair are (2^W - f, f); the result of every blend is the exact sum of all
//   weighted taps rounded once, half up (trilinear 3W, bilinear 2W dropped bits): the project's
//   one blend rule (golden/fixed/blend.hpp) at W bits.
// - Combine (eq. 5): per channel round(T * M / 255) with M = 255 (one), k_T or I_d.
//
// Memory: the taps' cells are read in one access of the eight banks per byte plane (four for
// true colour and CCC). A bank is read at most once per access: taps that share a cell (clamp
// and mirror edges, CCC taps in one block) share the read, a tap outside (border mode) reads
// nothing, and a level with weight 0 is not read.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "texram/layout.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"

namespace tmu::texram {

struct Tap {
  bool outside = false;   // border mode, outside the texture: the border colour
  uint32_t x = 0, y = 0;  // texel coordinates after the border operator
  BankCell cell;          // plane-0 cell (texels, or the CCC block holding the texel)
};

// The levels a sample reads and their blend (the rule above), in a pyramid of top + 1 levels.
struct LevelChoice {
  bool trilinear = false;      // blend two levels (weights 2^W - wl, wl), drop 3W bits
  int levels_read = 1;         // 1 (nearest, bilinear, or level weight 0) or 2
  int taps_per_level = 4;      // 1 (nearest) or 4 (x0y0, x1y0, x0y1, x1y1)
  std::array<int, 2> level{};  // levels of the (up to) two tap groups
  uint32_t wl = 0;             // W-bit weight of the second level
};
LevelChoice choose_levels(int top, const SamplerConfig& config, int32_t lambda);

// The taps of one axis at a level: bilinear (t0, t0 + 1, w the weight of t0 + 1) or nearest
// (t0 only); t0 is not yet resolved by the border operator.
struct Axis {
  int64_t t0 = 0;
  uint32_t w = 0;
};
Axis axis_taps(int32_t coord, int level, bool nearest, const Widths& widths);

// The border operator on texel coordinate x of an axis of n texels (n a power of two).
struct Resolved {
  bool outside;  // border colour: the tap reads nothing
  uint32_t x;
};
Resolved resolve_border(int64_t x, uint32_t n, Border border);

// Everything about one sample that comes before the memory.
struct SamplePlan : LevelChoice {
  std::array<uint32_t, 2> wx{}, wy{};  // W-bit weight of x1 and y1 per level
  std::array<std::array<Tap, 4>, 2> taps{};
  std::array<std::optional<uint32_t>, 8> bank_address;  // plane-0 address read in each bank
  int planes = 1;  // accesses per sample (plane p reads address + p)
};

// The address unit's first step: a request's (u, v) as TexCoord texels of level 0.
// kTexel passes them. kSphere reads each coordinate port's low 16 bits as UnitComp SQ2.14 (the
// bits above are ignored: a wrap, named) and maps the square [-1, 1]^2 of (uN, vN) onto level 0
// of the 2^a x 2^b texture, v pointing down the rows: u = (uN + 1) / 2 2^a, v = (1 - vN) / 2
// 2^b; in raw units (uN + 2^14) << (a - 7) and (2^14 - vN) << (b - 7), exact for sides of 128
// and more, floored (>> (7 - a)) below. At most 19 bits and a sign: no overflow. This is the
// host's sphere-map rule of view_maps.hpp (texel (i, j) stands for uN = 2 (i + 0.5) / S - 1).
Request texel_request(const Geometry& geometry, Addressing addressing, const Request& request);

// Address generation (after texel_request): levels, weights, taps and the bank access. Throws
// std::logic_error if two taps would need different cells of one bank (the layout guarantees they
// never do).
SamplePlan plan_sample(const Geometry& geometry, const SamplerConfig& config,
                       const Request& request);

// Bytes read by the access: bytes[bank][plane].
using AccessData = std::array<std::array<uint8_t, 4>, 8>;

// The RGBA8888 colour of a tap from the bytes its bank delivered.
uint32_t tap_colour(const Tap& tap, const AccessData& data, TexelKind kind,
                    const SamplerConfig& config, const Clut32& clut);

// The blend of the taps' colours (taps[level group][tap]), per channel, one rounding.
uint32_t blend_taps(const SamplePlan& plan, const std::array<std::array<uint32_t, 4>, 2>& colours,
                    const Widths& widths);

// round(t * m / 255) for 8-bit t and m, exactly: (x + (x >> 8)) >> 8 with x = t m + 128.
constexpr uint32_t mul255(uint32_t t, uint32_t m) {
  const uint32_t x = t * m + 128;
  return (x + (x >> 8)) >> 8;
}

// Eq. 5 on an RGBA8888 texture value.
uint32_t combine(uint32_t texture_rgba, const SamplerConfig& config, uint32_t shade_rgba);

// The bytes the access reads from the texture's banks.
AccessData read_access(const TexramTexture& texture, const SamplePlan& plan);

// The RGBA8888 colour of texel (x, y) of `level` (coordinates inside the level), read from the
// banks as a tap of the unit reads it.
uint32_t texel_rgba(const TexramTexture& texture, const SamplerConfig& config, int level,
                    uint32_t x, uint32_t y);

// The whole unit: plan, read, convert, blend, combine. Returns RGBA8888.
uint32_t sample(const TexramTexture& texture, const SamplerConfig& config, const Request& request,
                SamplePlan* plan_out = nullptr);

}  // namespace tmu::texram
