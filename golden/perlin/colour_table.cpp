#include "perlin/colour_table.hpp"

#include <algorithm>
#include <cmath>

namespace tmu::perlin {

std::array<uint32_t, kColourEntries> colour_table(const std::vector<ColourStop>& stops) {
  std::array<uint32_t, kColourEntries> table{};
  for (int i = 0; i < kColourEntries; ++i) {
    const double x = static_cast<double>(i) / (kColourEntries - 1);
    size_t k = 0;
    while (k + 1 < stops.size() && stops[k + 1].position < x) ++k;
    const ColourStop& a = stops[k];
    const ColourStop& b = stops[std::min(k + 1, stops.size() - 1)];
    const double span = b.position - a.position;
    const double t = span > 0 ? std::clamp((x - a.position) / span, 0.0, 1.0) : 0.0;
    uint32_t rgb = 0;
    for (int c = 0; c < 3; ++c) {
      const double v = a.rgb[static_cast<size_t>(c)] +
                       t * (b.rgb[static_cast<size_t>(c)] - a.rgb[static_cast<size_t>(c)]);
      rgb = (rgb << 8) | static_cast<uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
    }
    table[static_cast<size_t>(i)] = rgb;
  }
  return table;
}

}  // namespace tmu::perlin
