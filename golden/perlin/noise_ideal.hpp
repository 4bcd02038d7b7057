// The ideal (double precision) noise: the same lattice values R (they define the noise, as
// texels define a texture) at exact fractions, with the exact fade sm(t) = 3t^2 - 2t^3 and
// exact lerps, and the fractal sums of the exact octaves. It measures what the golden
// model's widths (F, S, B, X) cost.
#pragma once

namespace tmu::perlin::ideal {

// u, v, w in lattice units (SolidCoord's value). P in [-1, 1).
double noise(double u, double v, double w);

struct FractalSums {
  double fractal_sum = 0, turbulence = 0;
};
FractalSums fractal_sums(double u, double v, double w);

}  // namespace tmu::perlin::ideal
