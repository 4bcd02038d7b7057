// An ideal (double precision) colour rounded to RGBA8888 (R in bits 31:24), to set beside a
// golden colour: the nearest integer per channel, clamped to 0..255.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace tmu::texsim {

inline uint32_t round_rgba(const std::array<double, 4>& c) {
  uint32_t out = 0;
  for (size_t ch = 0; ch < 4; ++ch) {
    out |= static_cast<uint32_t>(std::lround(std::clamp(c[ch], 0.0, 255.0))) << (24 - 8 * ch);
  }
  return out;
}

}  // namespace tmu::texsim
