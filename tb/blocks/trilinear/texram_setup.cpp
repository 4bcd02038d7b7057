#include "blocks/trilinear/texram_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "formats/formats.hpp"

namespace tmu::tb {
namespace {

constexpr std::array<std::string_view, 6> kPatternNames = {"gradient", "checker", "noise",
                                                           "smooth",   "random",  "given"};
// The pattern draw: random bytes twice as often as each test pattern.
constexpr std::array<TexturePattern, 6> kPatternDraws = {
    TexturePattern::kGradient, TexturePattern::kChecker, TexturePattern::kNoise,
    TexturePattern::kSmooth,   TexturePattern::kRandom,  TexturePattern::kRandom};

// Uniform in lo..hi from the generator's raw output (no std distributions, so the stimulus is
// the same on every standard library).
int uniform(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

// log2 of a side: 0 (a one-texel side) now and then, else 1..8.
int draw_log2_side(std::mt19937_64& rng) { return rng() % 8 == 0 ? 0 : uniform(rng, 1, 8); }

std::string rgba_text(uint32_t v) { return fmt::format("0x{:08X}", v); }

}  // namespace

std::string_view name(TexturePattern p) { return kPatternNames[static_cast<size_t>(p)]; }

std::optional<TexturePattern> parse_pattern(std::string_view text) {
  for (size_t p = 0; p + 1 < kPatternNames.size(); ++p) {
    if (kPatternNames[p] == text) return static_cast<TexturePattern>(p);
  }
  return std::nullopt;
}

bool uses_clut(texram::TexelKind k) {
  return k == texram::TexelKind::kIndex || k == texram::TexelKind::kCcc;
}

bool four_planes(texram::TexelKind k) {
  return k == texram::TexelKind::kTrueColour || k == texram::TexelKind::kCcc;
}

TexramSetup with_overrides(TexramSetup s, const BlockOptions& o) {
  texram::SamplerConfig& c = s.config;
  if (o.tri_kind) c.kind = *o.tri_kind;
  if (o.tri_single_channel) c.single_channel = *o.tri_single_channel;
  if (o.tri_filter) c.filter = *o.tri_filter;
  if (o.tri_border_u) c.border_u = *o.tri_border_u;
  if (o.tri_border_v) c.border_v = *o.tri_border_v;
  if (o.tri_border_rgba) c.border_rgba = *o.tri_border_rgba;
  if (o.tri_combine) c.combine = *o.tri_combine;
  if (o.tri_constant_rgba) c.constant_rgba = *o.tri_constant_rgba;
  if (o.tri_log2_w) s.log2_w = *o.tri_log2_w;
  if (o.tri_log2_h) s.log2_h = *o.tri_log2_h;
  if (!o.tri_pattern.empty()) {
    const auto p = parse_pattern(o.tri_pattern);
    if (!p) {
      throw std::invalid_argument("trilinear: unknown pattern '" + o.tri_pattern +
                                  "' (gradient, checker, noise, smooth, random)");
    }
    s.pattern = *p;
  }
  c.widths = o.tri_widths;
  for (int b : {c.widths.sub_texel, c.widths.weight, c.widths.lod_frac}) {
    if (b < 1 || b > 8) throw std::invalid_argument("trilinear: widths must be 1..8 bits");
  }
  if (c.single_channel < 0 || c.single_channel > 3) {
    throw std::invalid_argument("trilinear: the single channel must be 0..3");
  }
  for (int side : {s.log2_w, s.log2_h}) {
    if (side < 0 || side > formats::kMaxMipLog2) {
      throw std::invalid_argument(
          fmt::format("trilinear: log2 of a side must be 0..{}", formats::kMaxMipLog2));
    }
  }
  return s;
}

TexramSetup draw_texram_setup(std::mt19937_64& rng, const BlockOptions& o) {
  TexramSetup s;
  texram::SamplerConfig& c = s.config;
  c.kind = static_cast<texram::TexelKind>(rng() % 5);
  s.log2_w = draw_log2_side(rng);
  s.log2_h = rng() % 3 == 0 ? s.log2_w : draw_log2_side(rng);
  s.pattern = kPatternDraws[rng() % kPatternDraws.size()];
  c.single_channel = static_cast<int>(rng() % 4);
  c.filter = static_cast<texram::Filter>(rng() % 3);
  c.border_u = static_cast<texram::Border>(rng() % 4);
  c.border_v = rng() % 3 == 0 ? c.border_u : static_cast<texram::Border>(rng() % 4);
  c.border_rgba = static_cast<uint32_t>(rng());
  c.combine = static_cast<texram::Combine>(rng() % 3);
  c.constant_rgba = static_cast<uint32_t>(rng());
  s.content = static_cast<uint32_t>(rng());
  return with_overrides(s, o);
}

TexramSetup first_texram_setup(const BlockOptions& o) {
  std::mt19937_64 rng(o.seed ^ 0x7E1A'B10C'0000'0001ull);
  return draw_texram_setup(rng, o);
}

std::string texram_repro_options(const BlockOptions& o) {
  std::vector<std::string> parts;
  const auto rgba = [](uint32_t v) { return fmt::format("0x{:08X}", v); };
  if (o.tri_kind) parts.push_back(fmt::format("--config {}", texram::name(*o.tri_kind)));
  if (o.tri_single_channel) {
    parts.push_back(fmt::format("--channel {}", "rgba"[*o.tri_single_channel & 3]));
  }
  if (o.tri_filter) parts.push_back(fmt::format("--filter {}", texram::name(*o.tri_filter)));
  if (o.tri_border_u) parts.push_back(fmt::format("--border-u {}", texram::name(*o.tri_border_u)));
  if (o.tri_border_v) parts.push_back(fmt::format("--border-v {}", texram::name(*o.tri_border_v)));
  if (o.tri_border_rgba) parts.push_back("--border-colour " + rgba(*o.tri_border_rgba));
  if (o.tri_combine) parts.push_back(fmt::format("--combine {}", texram::name(*o.tri_combine)));
  if (o.tri_constant_rgba) parts.push_back("--constant " + rgba(*o.tri_constant_rgba));
  if (o.tri_log2_w) parts.push_back(fmt::format("--log2-w {}", *o.tri_log2_w));
  if (o.tri_log2_h) parts.push_back(fmt::format("--log2-h {}", *o.tri_log2_h));
  if (!o.tri_pattern.empty()) parts.push_back("--pattern " + o.tri_pattern);
  if (!o.tri_image.empty()) parts.push_back("--image " + o.tri_image);
  if (!(o.tri_widths == texram::Widths{})) {
    parts.push_back(fmt::format("--widths {},{},{}", o.tri_widths.sub_texel, o.tri_widths.weight,
                                o.tri_widths.lod_frac));
  }
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : " ") + p;
  return out;
}

std::string describe(const TexramSetup& s, const std::string& content) {
  const texram::SamplerConfig& c = s.config;
  std::string kind(texram::name(c.kind));
  if (c.kind == texram::TexelKind::kSingle) {
    kind += fmt::format(" (channel {})", "RGBA"[c.single_channel & 3]);
  }
  return fmt::format(
      "{} {} x {} ({}), {}, border u {} v {} ({}), combine {}{}, widths {},{},{}{}", kind,
      1 << s.log2_w, 1 << s.log2_h, content, texram::name(c.filter), texram::name(c.border_u),
      texram::name(c.border_v), rgba_text(c.border_rgba), texram::name(c.combine),
      c.combine == texram::Combine::kConstant ? fmt::format(" {}", rgba_text(c.constant_rgba)) : "",
      c.widths.sub_texel, c.widths.weight, c.widths.lod_frac,
      c.addressing == texram::Addressing::kSphere ? ", sphere-map addressing" : "");
}

namespace {

constexpr std::array<texram::TexelKind, 5> kKinds = {
    texram::TexelKind::kLuminance, texram::TexelKind::kIndex, texram::TexelKind::kTrueColour,
    texram::TexelKind::kSingle, texram::TexelKind::kCcc};
constexpr std::array<texram::Filter, 3> kFilters = {
    texram::Filter::kNearest, texram::Filter::kBilinear, texram::Filter::kTrilinear};
constexpr std::array<texram::Border, 4> kBorders = {texram::Border::kWrap, texram::Border::kClamp,
                                                    texram::Border::kBorder,
                                                    texram::Border::kMirror};
constexpr std::array<texram::Combine, 3> kCombines = {
    texram::Combine::kOne, texram::Combine::kConstant, texram::Combine::kShade};

template <class T, size_t N>
std::vector<T> values(const std::optional<T>& fixed, const std::array<T, N>& all) {
  return fixed ? std::vector<T>{*fixed} : std::vector<T>(all.begin(), all.end());
}

template <class T>
bool has(const std::vector<T>& v, T x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

}  // namespace

TexramSetup tour_setup(size_t i, int log2_w, int log2_h, const BlockOptions& options) {
  TexramSetup s;
  texram::SamplerConfig& c = s.config;
  c.kind = kKinds[i % kKinds.size()];
  c.filter = kFilters[i % kFilters.size()];
  c.border_u = kBorders[i % kBorders.size()];
  c.border_v = kBorders[(i + i / 4) % kBorders.size()];
  c.combine = kCombines[(i + i / 5) % kCombines.size()];
  c.single_channel = static_cast<int>(i % 4);
  c.border_rgba = 0x1234'5678u * static_cast<uint32_t>(i + 1);
  c.constant_rgba = 0x9E37'79B9u * static_cast<uint32_t>(i + 1);
  s.log2_w = log2_w;
  s.log2_h = log2_h;
  s.pattern = static_cast<TexturePattern>(i % 5);
  s.content = 0x70C0'0000u + static_cast<uint32_t>(i);
  return with_overrides(s, options);
}

bool TexramChoices::any(texram::TexelKind k) const { return has(kinds, k); }
bool TexramChoices::any(texram::Filter f) const { return has(filters, f); }
bool TexramChoices::any(texram::Border b) const { return has(borders_u, b) || has(borders_v, b); }
bool TexramChoices::any(texram::Combine c) const { return has(combines, c); }

TexramChoices texram_choices(const BlockOptions& o, const TexramSetup& first) {
  TexramChoices c;
  const bool given = first.pattern == TexturePattern::kGiven;
  const bool given_texture = given && o.tri_image.empty();
  c.kinds = given_texture ? std::vector{first.config.kind} : values(o.tri_kind, kKinds);
  c.filters = values(o.tri_filter, kFilters);
  c.borders_u = values(o.tri_border_u, kBorders);
  c.borders_v = values(o.tri_border_v, kBorders);
  c.combines = values(o.tri_combine, kCombines);
  const std::optional<int> lw = given ? first.log2_w : o.tri_log2_w;
  const std::optional<int> lh = given ? first.log2_h : o.tri_log2_h;
  c.one_texel_side = lw.value_or(0) == 0 || lh.value_or(0) == 0;
  c.non_square = !(lw && lh && *lw == *lh);
  c.side_64 = lw.value_or(6) >= 6 && lh.value_or(6) >= 6;
  c.largest_rgba = c.any(texram::TexelKind::kTrueColour) &&
                   lw.value_or(formats::kMaxMipLog2) == formats::kMaxMipLog2 &&
                   lh.value_or(formats::kMaxMipLog2) == formats::kMaxMipLog2;
  c.painted = !given;
  return c;
}

std::vector<std::string> config_cases(const TexramChoices& c) {
  std::vector<std::string> cases;
  for (texram::TexelKind k : c.kinds) cases.push_back(fmt::format("kind {}", texram::name(k)));
  for (texram::Filter f : c.filters) cases.push_back(fmt::format("filter {}", texram::name(f)));
  for (texram::Border b : c.borders_u) cases.push_back(fmt::format("border u {}", texram::name(b)));
  for (texram::Border b : c.borders_v) cases.push_back(fmt::format("border v {}", texram::name(b)));
  for (texram::Combine m : c.combines) cases.push_back(fmt::format("combine {}", texram::name(m)));
  return cases;
}

void cover_config(const TexramSetup& s, std::map<std::string, uint64_t>& cov) {
  const texram::SamplerConfig& c = s.config;
  ++cov[fmt::format("kind {}", texram::name(c.kind))];
  ++cov[fmt::format("filter {}", texram::name(c.filter))];
  ++cov[fmt::format("border u {}", texram::name(c.border_u))];
  ++cov[fmt::format("border v {}", texram::name(c.border_v))];
  ++cov[fmt::format("combine {}", texram::name(c.combine))];
}

}  // namespace tmu::tb
