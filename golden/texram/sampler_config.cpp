#include "texram/sampler_config.hpp"

#include <array>
#include <utility>

namespace tmu::texram {
namespace {

template <class E, size_t N>
std::optional<E> parse(const std::array<std::pair<E, std::string_view>, N>& names,
                       std::string_view s) {
  for (const auto& [e, n] : names) {
    if (n == s) return e;
  }
  return std::nullopt;
}

template <class E, size_t N>
std::string_view name_of(const std::array<std::pair<E, std::string_view>, N>& names, E e) {
  for (const auto& [v, n] : names) {
    if (v == e) return n;
  }
  return "?";
}

constexpr std::array<std::pair<TexelKind, std::string_view>, 5> kKinds{
    {{TexelKind::kLuminance, "luminance"},
     {TexelKind::kIndex, "index"},
     {TexelKind::kTrueColour, "rgba"},
     {TexelKind::kSingle, "single"},
     {TexelKind::kCcc, "ccc"}}};
constexpr std::array<std::pair<Filter, std::string_view>, 3> kFilters{
    {{Filter::kNearest, "nearest"},
     {Filter::kBilinear, "bilinear"},
     {Filter::kTrilinear, "trilinear"}}};
constexpr std::array<std::pair<Border, std::string_view>, 4> kBorders{
    {{Border::kWrap, "wrap"},
     {Border::kClamp, "clamp"},
     {Border::kBorder, "border"},
     {Border::kMirror, "mirror"}}};
constexpr std::array<std::pair<Combine, std::string_view>, 3> kCombines{
    {{Combine::kOne, "one"}, {Combine::kConstant, "constant"}, {Combine::kShade, "shade"}}};

}  // namespace

std::string_view name(TexelKind k) { return name_of(kKinds, k); }
std::string_view name(Filter f) { return name_of(kFilters, f); }
std::string_view name(Border b) { return name_of(kBorders, b); }
std::string_view name(Combine c) { return name_of(kCombines, c); }
std::string_view name(Addressing a) { return a == Addressing::kSphere ? "sphere" : "texel"; }
std::optional<TexelKind> parse_texel_kind(std::string_view s) { return parse(kKinds, s); }
std::optional<Filter> parse_filter(std::string_view s) { return parse(kFilters, s); }
std::optional<Border> parse_border(std::string_view s) { return parse(kBorders, s); }
std::optional<Combine> parse_combine(std::string_view s) { return parse(kCombines, s); }

}  // namespace tmu::texram
