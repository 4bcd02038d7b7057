#include "clipmap/tile_centre.hpp"

#include <algorithm>
#include <cmath>

namespace tmu::clipmap {

Region centred_region(const Config& c, int level, double eye_u, double eye_v) {
  const int64_t tile = int64_t{1} << c.log2_tile;
  const int64_t side = int64_t{1} << (c.log2_virtual - level);
  const auto origin = [&](double eye) {
    const auto at_level = static_cast<int64_t>(std::floor(std::ldexp(eye, -level)));
    return static_cast<uint32_t>(std::clamp<int64_t>(at_level - tile / 2, 0, side - tile));
  };
  const uint32_t x = origin(eye_u), y = origin(eye_v);
  return {x, y, static_cast<uint32_t>(x + tile), static_cast<uint32_t>(y + tile)};
}

Regions centred_regions(const Config& c, double eye_u, double eye_v) {
  Regions r{};
  for (int l = 0; l < c.clipped_levels(); ++l) {
    r[static_cast<size_t>(l)] = centred_region(c, l, eye_u, eye_v);
  }
  return r;
}

}  // namespace tmu::clipmap
