// The host's centre rule for a clip-map's tiles (003 §I: "tiles ... at or near the current field
// of view", each level's tile centred on the eyepoint): the tile of clipped level l starts at
//   origin = clamp(floor(eye / 2^l) - T / 2, 0, 2^(V-l) - T)
// per axis, eye in texels of the virtual level 0: centred on the eye, and slid back inside the
// virtual texture at its edges, so a tile never wraps around the texture (a region is one
// rectangle). For T >= 8 the tiles are nested with a texel to spare: level l + 1's tile holds
// level l's and one texel more on every side that is not the texture's edge, which is what
// per-tap substitution needs to stay one access (clipmap.hpp).
#pragma once

#include "clipmap/clipmap.hpp"

namespace tmu::clipmap {

Region centred_region(const Config& config, int level, double eye_u, double eye_v);
// Every clipped level's; levels from C up stay empty (a whole level needs no region).
Regions centred_regions(const Config& config, double eye_u, double eye_v);

}  // namespace tmu::clipmap
