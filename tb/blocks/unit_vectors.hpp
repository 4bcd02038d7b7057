// Random directions as UnitComp vectors (SQ2.14), the stimulus of the blocks that take one: the
// normal encoder (001 §4.1) and the cube map addressing unit (000 §7).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "formats/formats.hpp"

namespace tmu::tb {

// A direction uniform on the sphere, as doubles.
inline std::array<double, 3> random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  while (true) {
    const std::array<double, 3> v = {g(rng), g(rng), g(rng)};
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 1e-6) return {v[0] / len, v[1] / len, v[2] / len};
  }
}

// dir scaled to `length` in UnitComp LSBs, each component rounded and saturated to the port's
// 16 bits (a length near 2 saturates its largest component).
inline std::array<int16_t, 3> unit_comps(const std::array<double, 3>& dir, double length) {
  const double s = length * (1 << formats::kUnitComp.frac_bits);
  std::array<int16_t, 3> out{};
  for (int i = 0; i < 3; ++i) {
    out[i] = static_cast<int16_t>(std::clamp(std::lround(dir[i] * s), -32768L, 32767L));
  }
  return out;
}

}  // namespace tmu::tb
