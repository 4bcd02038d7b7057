// The ideal (double precision) cube environment map addressing (000 §7): a reflection vector to
// one of six faces and an exact texel coordinate on it, by its own code. It shares with golden
// (cube_map.hpp) only definitions: OpenGL's face order and face coordinates, and the tie rule
// of the major axis (x before y before z), listed in docs/deflection.md.
#pragma once

#include <cstdint>

namespace tmu::deflect {

struct CubeIdeal {
  uint32_t face = 0;    // 0 .. 5: +X, -X, +Y, -Y, +Z, -Z
  double u = 0, v = 0;  // texels of a face of 2^face_log2, centres at i + 0.5
};
CubeIdeal cube_address_ideal(double x, double y, double z, int face_log2);

}  // namespace tmu::deflect
