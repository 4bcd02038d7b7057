// The ideal (double precision) noise: the same lattice values R (they define the noise, as
// texels define a texture) at exact fractions, with the exact fade sm(t) = 3t^2 - 2t^3 and
// exact lerps, and the fractal sums of the exact octaves. It measures what the golden
// model's widths (F, S, B, X) cost.
//
// It shares with golden only the definitions of noise_definition.hpp (T's rows, the widths);
// the hash is its own code: T as a sum of the matrix's columns (golden takes each row's
// parity), and its own lattice indices from the exact coordinates.
#pragma once

#include <cstdint>

namespace tmu::perlin::ideal {

// The scramble T of a 12-bit value (bits above 12 are ignored).
uint32_t scramble(uint32_t x);
// The lattice value R at the lattice point (i, j, k), any integers (the lattice repeats every
// 4096 units): in [-1, 1), a multiple of 1/128.
double lattice_value(int64_t i, int64_t j, int64_t k);

// u, v, w in lattice units (SolidCoord's value). P in [-1, 1).
double noise(double u, double v, double w);

struct FractalSums {
  double fractal_sum = 0, turbulence = 0;
};
FractalSums fractal_sums(double u, double v, double w);

}  // namespace tmu::perlin::ideal
