// How the TEXRAM's trilinear unit is configured (000 §6), what a request carries, and the
// internal widths the accuracy sweep varies.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tmu::texram {

// The texel configurations of §6, plus CCC-compressed textures.
enum class TexelKind : uint8_t {
  kLuminance,   // 8-bit grey: (L, L, L, 255)
  kIndex,       // 8-bit indices into the 256 x RGBA8888 CLUT, interpolated after the look-up
  kTrueColour,  // RGBA8888, four byte planes: four accesses per sample
  kSingle,      // one 8-bit colour component (one device of a 3- or 4-chip system)
  kCcc,         // CCC blocks (000 §3): four byte planes of the block word, decoded per tap
};

enum class Filter : uint8_t {
  kNearest,    // the nearest texel of level round(lambda)
  kBilinear,   // bilinear in level round(lambda)
  kTrilinear,  // bilinear in levels floor(lambda) and floor(lambda) + 1, blended by the fraction
};

// OpenGL's border operators (§6), per axis.
enum class Border : uint8_t {
  kWrap,    // repeat
  kClamp,   // clamp to the edge texel
  kBorder,  // outside the texture the tap takes the border colour
  kMirror,  // mirrored repeat
};

// The selection of eq. 5, C_d = (I_d | k_T | 1) . T.
enum class Combine : uint8_t {
  kOne,       // T unmodified
  kConstant,  // k_T, a register
  kShade,     // I_d, the shaded intensity the rasterizer sends with the request
};

// How the address unit reads a request's (u, v) (trilinear.hpp: texel_request). Only the
// trilinear unit has the choice (its configuration field `addressing`); the footprint unit's
// probes are texels.
enum class Addressing : uint8_t {
  kTexel,   // TexCoord: texels of level 0
  kSphere,  // a sphere map's (uN, vN) from the coordinate generator (001 §5), UnitComp
};

// The unit's internal precision, each 1..8 bits (the request ports carry 8 fraction bits).
struct Widths {
  int sub_texel = 8;  // fraction bits of a coordinate within a level
  int weight = 8;     // filter weight bits: weights (2^w - f, f)
  int lod_frac = 8;   // fraction bits of lambda
  friend bool operator==(const Widths&, const Widths&) = default;
};

struct SamplerConfig {
  TexelKind kind = TexelKind::kLuminance;
  int single_channel = 0;  // kSingle: the output channel, 0 = R .. 3 = A
  Filter filter = Filter::kTrilinear;
  Border border_u = Border::kWrap;
  Border border_v = Border::kWrap;
  uint32_t border_rgba = 0;  // RGBA8888
  Combine combine = Combine::kOne;
  uint32_t constant_rgba = 0;  // k_T, RGBA8888
  Addressing addressing = Addressing::kTexel;
  Widths widths;
  friend bool operator==(const SamplerConfig&, const SamplerConfig&) = default;
};

// One sample request: raw port values.
struct Request {
  int32_t u = 0;       // TexCoord SQ16.8, texels of level 0, texel centres at i + 0.5
  int32_t v = 0;       // TexCoord SQ16.8
  int32_t lambda = 0;  // Lod SQ6.8
  uint32_t shade = 0;  // I_d, RGBA8888
};

// Names as the command line spells them ("luminance", "trilinear", "mirror", "shade", ...).
std::string_view name(TexelKind k);
std::string_view name(Filter f);
std::string_view name(Border b);
std::string_view name(Combine c);
std::string_view name(Addressing a);
std::optional<TexelKind> parse_texel_kind(std::string_view s);
std::optional<Filter> parse_filter(std::string_view s);
std::optional<Border> parse_border(std::string_view s);
std::optional<Combine> parse_combine(std::string_view s);

// Packs / unpacks RGBA8888: R in 31:24 .. A in 7:0.
constexpr uint32_t rgba(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
  return (r << 24) | (g << 16) | (b << 8) | a;
}
constexpr uint32_t channel(uint32_t rgba8888, int c) { return (rgba8888 >> (24 - 8 * c)) & 0xFFu; }

}  // namespace tmu::texram
