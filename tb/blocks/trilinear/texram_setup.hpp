// One environment of the TEXRAM sampling path (trilinear, footprint): the trilinear unit's
// configuration and the texture the memory holds, as a configuration item names it. The
// first environment of a block is drawn from its seed, later ones (a random run draws a new one
// every few thousand items) from the run's generator; BlockOptions::tri_* fix what they set.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "blocks/registry.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::tb {

// What a texture holds (the EnvPattern field): a test pattern, random bytes in every level and
// the CLUT, or a given texture (an image file, a scene's).
enum class TexturePattern : uint8_t { kGradient, kChecker, kNoise, kSmooth, kRandom, kGiven };
std::string_view name(TexturePattern p);
// "gradient" .. "random"; nullopt for another name.
std::optional<TexturePattern> parse_pattern(std::string_view text);

struct TexramSetup {
  texram::SamplerConfig config;  // config.widths: the block's parameters, not in the item
  int log2_w = 0, log2_h = 0;    // the texture's size, 0..10 each
  TexturePattern pattern = TexturePattern::kRandom;
  uint32_t content = 0;  // the seed of the pattern's or the random bytes' content
};

// Whether a kind reads the CLUT (index, CCC), and has four byte planes (true colour, CCC).
bool uses_clut(texram::TexelKind kind);
bool four_planes(texram::TexelKind kind);

// An environment drawn from the generator: kind, size (log2 1..8 a side, now and then 0),
// content, single channel, filter, borders, colours, combine; then every field the options set
// overrides its draw (every draw is made, so an override changes nothing else). The widths are
// options.tri_widths. Throws std::invalid_argument for widths outside 1..8, a channel outside
// 0..3, a side outside 0..10 or an unknown pattern.
TexramSetup draw_texram_setup(std::mt19937_64& rng, const BlockOptions& options);
// The options' overrides applied to `setup` (for environments written by hand).
TexramSetup with_overrides(TexramSetup setup, const BlockOptions& options);
// The first environment of a block: drawn from options.seed.
TexramSetup first_texram_setup(const BlockOptions& options);
// Entry i of a tour of environments, of the given size: over 15 entries every kind with every
// filter, every border mode on both axes (alike and not), every combine and single channel;
// a pattern or random bytes. The options' overrides applied.
TexramSetup tour_setup(size_t i, int log2_w, int log2_h, const BlockOptions& options);

// The `texsim cosim` options that set what `options` sets of the environment (tri_*).
std::string texram_repro_options(const BlockOptions& options);

// One line: kind, size, what the texture holds (`content`), filter, borders, combine, widths.
std::string describe(const TexramSetup& setup, const std::string& content);

// What the options leave possible for the environments of a block whose first is `first`: the
// values each configuration field can take (an option fixes its field; a given texture its
// kind and size, a given image its size), and the texture shapes.
struct TexramChoices {
  std::vector<texram::TexelKind> kinds;
  std::vector<texram::Filter> filters;
  std::vector<texram::Border> borders_u, borders_v;
  std::vector<texram::Combine> combines;
  bool one_texel_side = true, non_square = true;
  bool side_64 = true;       // both sides can be 64 texels or more
  bool largest_rgba = true;  // a true-colour texture of 1024 x 1024 (cell addresses >= 2^20)
  bool painted = true;       // a texture built from a pattern or random bytes (not given)
  bool any(texram::TexelKind k) const;
  bool any(texram::Filter f) const;
  bool any(texram::Border b) const;  // on either axis
  bool any(texram::Combine c) const;
};
TexramChoices texram_choices(const BlockOptions& options, const TexramSetup& first);
// The coverage cases of the configuration: "kind K", "filter F", "border u B", "border v B",
// "combine C" for every value the choices hold, and their counting for the setup in effect.
std::vector<std::string> config_cases(const TexramChoices& choices);
void cover_config(const TexramSetup& setup, std::map<std::string, uint64_t>& coverage);

}  // namespace tmu::tb
