// The ideal (double precision) clip-map unit (003): exact coordinates, lambda and weights on the
// virtual texture's ideal levels (texram/trilinear_ideal.hpp: its exact box pyramid of the
// source, its texels and border operators), and the two substitution rules by its own code on
// exact coordinates: where golden's rounded coordinates and the exact ones fall on different
// sides of a tile's edge, the two substitute differently (tests/clipmap_test.cpp counts it). It
// shares with golden only definitions: the sampler's configuration (sampler_config.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "texram/sampler_config.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::clipmap::ideal {

// The texels a clipped level's tile holds: [x0, x1) x [y0, y1).
struct Tile {
  uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct Setup {
  int log2_virtual = 8;     // the virtual level 0 is 2^V x 2^V
  int log2_tile = 5;        // levels 0 .. V - t - 1 are clipped
  bool per_tap = false;     // else per sample
  std::vector<Tile> tiles;  // one per clipped level
};

// u, v in texels of the virtual level 0, lambda in levels; RGBA 0..255 each. `texture` is the
// whole virtual texture (its levels as the ideal sees them).
std::array<double, 4> sample(const texram::IdealTexture& texture,
                             const texram::SamplerConfig& config, const Setup& setup, double u,
                             double v, double lambda, uint32_t shade = 0);

}  // namespace tmu::clipmap::ideal
