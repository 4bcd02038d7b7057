// A material's 128-entry colour table from a few colour stops (the host's tool, as
// `texsim bumpmap` is the bump map's): entry i is the colour at position i / 127, linear
// between the stops around it (the first and last stops extend to the ends), each channel
// round(255 c) clamped to 0..255, RGB888.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "perlin/materials.hpp"

namespace tmu::perlin {

struct ColourStop {
  double position = 0;                 // 0..1
  std::array<double, 3> rgb{0, 0, 0};  // 0..1
};

// `stops` sorted by position (not empty).
std::array<uint32_t, kColourEntries> colour_table(const std::vector<ColourStop>& stops);

}  // namespace tmu::perlin
