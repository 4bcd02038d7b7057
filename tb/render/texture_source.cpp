#include "render/texture_source.hpp"

#include <algorithm>
#include <cmath>

#include "common/test_patterns.hpp"

namespace tmu::render {
namespace {

Rgb8 rgb8(const glm::dvec3& c) {
  auto ch = [](double v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
  };
  return {ch(c.r), ch(c.g), ch(c.b)};
}

}  // namespace

ImageRgb8 source_image(const host::TextureSource& t) {
  if (t.kind == host::TextureSource::Kind::kImage) return read_image(t.path);
  const Rgb8 c0 = t.colours.size() > 0 ? rgb8(t.colours[0]) : Rgb8{20, 20, 20};
  const Rgb8 c1 = t.colours.size() > 1 ? rgb8(t.colours[1]) : Rgb8{235, 235, 235};
  if (t.pattern == "checker") return patterns::checker(t.width, t.height, t.cell, c0, c1);
  if (t.pattern == "text") return patterns::text(t.width, t.height, t.text, c0, c1);
  if (t.pattern == "gradient") return patterns::gradient(t.width, t.height);
  if (t.pattern == "noise") return patterns::noise(t.width, t.height, t.seed);
  if (t.pattern == "smooth") return patterns::smooth_field(t.width, t.height, t.seed);
  return patterns::default_image(t.width, t.height);
}

}  // namespace tmu::render
