// Golden model of the cube environment map's addressing (000 §7, §5 "fourth": "dividing by
// the largest component of the vector"): a reflection vector R to one of six faces and a
// texel coordinate on it. R is the coordinate generator's (uR, vR, wR) (coord_tables.hpp),
// so the cube is held in the view frame, like 001's spherical map: the host re-projects the
// environment when the view or the object turns. This file is the specification the hls and
// rtl models match.
//
// 1. The major axis: the largest |component|, ties to the earlier of x, y, z (so an edge or a
//    corner of the cube belongs to one face: x before y before z). Face = 2 axis + (major < 0)
//    in OpenGL's order +X, -X, +Y, -Y, +Z, -Z; the zero vector is face +X.
// 2. OpenGL's face coordinates (sc, tc) and ma = |major|:
//      +X: -z, -y   -X: +z, -y   +Y: +x, +z   -Y: +x, -z   +Z: +x, -y   -Z: -x, -y
// 3. r = divide_ratio(|sc|, ma) (the normal encoder's divider, UQ1.16; |sc| <= ma), then
//    s = 2^15 + sign(sc) r / 2 (truncated: (r >> 1)), UQ0.16 in [0, 1], likewise t; ma = 0
//    gives the face centre.
// 4. The texel coordinate on a face of 2^L texels, TexCoord SQ16.8 (texel centres at
//    i + 0.5, as every texture): u = (s 2^L + 2^7) >> 8 rounded half up, likewise v. An edge
//    of the cube (s = 0 or 1) lands on the face's border: the map samples it with clamp.
#pragma once

#include <cstdint>

namespace tmu::deflect {

struct CubeAddress {
  uint32_t face = 0;     // 0 .. 5: +X, -X, +Y, -Y, +Z, -Z
  int32_t u = 0, v = 0;  // TexCoord SQ16.8 on the face
};

CubeAddress cube_address(int32_t x, int32_t y, int32_t z, int face_log2, int seed_bits = 7);

// Its ideal, by its own code: deflect/cube_ideal.hpp.

}  // namespace tmu::deflect
