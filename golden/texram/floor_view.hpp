// A test view for the texture unit: a textured floor seen in perspective down to the horizon,
// one request per pixel below it, with u, v and lambda computed analytically (exactly) from the
// projection. It exercises every level from magnification near the viewer to the top level at
// the horizon, and is the "rendered test pattern" of the accuracy sweep.
#pragma once

#include <cstdint>
#include <vector>

namespace tmu::texram {

struct ViewRequest {
  int x = 0, y = 0;     // pixel
  double u = 0, v = 0;  // texels of level 0
  double lambda = 0;    // log2 of the larger pixel footprint side, in level-0 texels
};

// The floor below the horizon of a width x height image: the texture (texels_u x texels_v)
// repeats `tiles` times across the view's width at the bottom row.
std::vector<ViewRequest> floor_view(int width, int height, uint32_t texels_u, uint32_t texels_v,
                                    double tiles = 2.0);

}  // namespace tmu::texram
