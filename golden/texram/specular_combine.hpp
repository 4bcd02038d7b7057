// Golden model of the specular combine (000 §7 eq. 6, §8 eq. 7):
//   C = (C_d | I_d) + R . (E | I_s)
// C_d is the textured, diffusely shaded colour the trilinear unit delivers (eq. 5), E the
// environment-map sample or I_s the specular shading-map sample, and R the reflectance: the
// register k_s (eq. 6) or the reflectance map's sample k_s(u, v) at the texture's (u, v)
// (eq. 7). All three are RGBA8888 (R in 31:24 .. A in 7:0), so a coloured reflectance (gold,
// copper) is one RGB triple. Per colour channel c of R, G, B:
//   C_c = min(255, D_c + mul255(E_c, R_c))      mul255 = round(x y / 255), trilinear.hpp
// and the alpha of C is D's alpha (reflections add light, not coverage). This file is the
// specification the hls and rtl models match.
#pragma once

#include <algorithm>
#include <cstdint>

#include "texram/trilinear.hpp"

namespace tmu::texram {

constexpr uint32_t specular_combine(uint32_t diffuse_rgba, uint32_t specular_rgba,
                                    uint32_t reflectance_rgba) {
  uint32_t out = diffuse_rgba & 0xFFu;
  for (int shift = 24; shift >= 8; shift -= 8) {
    const uint32_t d = (diffuse_rgba >> shift) & 0xFFu;
    const uint32_t e = (specular_rgba >> shift) & 0xFFu;
    const uint32_t r = (reflectance_rgba >> shift) & 0xFFu;
    out |= std::min(255u, d + mul255(e, r)) << shift;
  }
  return out;
}

}  // namespace tmu::texram
