// Golden model of the procedural noise unit (002 §4.1): value noise on the integer lattice
// with xor-table hashing, the fade sm(x) = 3x^2 - 2x^3 from a table, trilinear interpolation
// with f(a, b, c) = a + c (b - a), and the two fractal sums of four octaves. This file is the
// specification the hls and rtl models match.
//
// Coordinates: SolidCoord SQ12.12 (the fragment's object-space (u, v, w), already scaled by
// the material). The unit keeps F fraction bits (truncation: floor towards -infinity, so
// negative coordinates have the same cells as positive ones), splits each into the lattice
// index i = floor(x) and the fraction t in [0, 1) (F bits).
//
// Lattice values R(x1, x2, x3) (002 Fig. 4.5, "xor tables" [Rau91]): T is a constant 12 x 12
// bit matrix (kXorRows; bit j of T(x) is the parity of x & kXorRows[j]), invertible so that T
// permutes the 12-bit values. The scrambles are chained through a 12-bit adder, and the last
// coordinate is added twice:
//   h = T((T((T((T(x1) + x2) mod 2^12) + x3) mod 2^12) + x3) mod 2^12)
// with x1, x2, x3 the lattice indices mod 2^12 (two's complement: -1 is 4095). The thesis
// scrambles three times (its figure is lost); the adders and the fourth scramble are ours,
// because T is linear over GF(2): with xors alone, or with three scrambles, a coordinate that
// reaches the output through one T only gives values whose xor over four aligned neighbours
// (x, x+1, x+2, x+3 with x = 0 mod 4) is zero: measured, half of all such groups along w with
// three scrambles, 0.8 % with four (1/256 = 0.4 % for random values; tests/perlin_test.cpp).
// The lattice value is h's top 8 bits as a signed SQ0.7 number in [-1, 1). The noise
// therefore repeats every 4096 units along each axis: beyond that it wraps, by definition,
// never undefined.
//
// Fade: a table of 2^S entries, S <= F, indexed by t's top S bits; entry k holds
// round(sm(k / 2^S) 2^B) (half up), UQ1.B, so the weight pair is (2^B - c, c). In integers:
// ((3 k^2 2^S - 2 k^3) 2^B + 2^(3S - 1)) >> 3S, exact.
// The ports (formats.def NoiseValue, FractalValue) carry the default X = 4; other widths are
// for the golden model's sweep.
//
// Interpolation: the eight lattice values are extended to SQ0.(7 + X) (X more fraction bits,
// zero) and blended by seven lerps, u first (four), then v (two), then w (one), each
//   f(a, b, c) = a + ((c (b - a) + 2^(B-1)) >> B)         (rounded half up, one rounding)
// which stays between a and b: the noise P is SQ0.(7 + X) in [-1, 1).
//
// Fractal sums (002 §4.1.1) of four octaves i = 0..3, octave i at the coordinates 2^i (u, v, w)
// (a shift: the lattice indices grow and wrap as above), amplitude 2^-i:
//   fractal sum  = sum_i 2^-i P_i         (the noise itself: gases, 002 §4.2.2)
//   turbulence   = sum_i 2^-i |P_i|       (its absolute value: marble, wood, brick)
// The thesis's formula block swaps the two names; its prose and Perlin's usage are as here.
// The accumulator is SQ2.(10 + X): the shifts are exact, and the largest sum, 15/8 of the
// largest |P|, fits (turbulence of four octaves of -1 is 1.875).
//
// The widths and T's rows are definitions, shared with the ideal model: noise_definition.hpp.
#pragma once

#include <cstdint>

#include "formats/formats.hpp"
#include "perlin/noise_definition.hpp"

namespace tmu::perlin {

struct NoiseConfig {
  int frac_bits = 8;        // F: coordinate fraction bits the unit uses, 1..12
  int fade_index_bits = 8;  // S: fade-table index bits, 1..F
  int fade_bits = 8;        // B: fade-table entry fraction bits (UQ1.B), 2..12
  int lerp_extra_bits = 4;  // X: fraction bits below the lattice values' 7, 0..8
  friend bool operator==(const NoiseConfig&, const NoiseConfig&) = default;
};

// Throws std::invalid_argument naming the field for a value out of range.
void check(const NoiseConfig& config);

// The scramble T of one 12-bit value, and the lattice value R as raw SQ0.7 (-128..127).
uint32_t xor_table(uint32_t x);
int32_t lattice_value(uint32_t x1, uint32_t x2, uint32_t x3);

// Entry k of the fade table (UQ1.B).
uint32_t fade_entry(const NoiseConfig& config, uint32_t k);

// One lerp of SQ0.(7 + X) values with weight c (UQ1.B).
int32_t lerp(int32_t a, int32_t b, uint32_t c, int fade_bits);

// P at raw SolidCoord coordinates (any int64: only the low 24 + octave bits matter), raw
// SQ0.(7 + X).
int32_t noise(const NoiseConfig& config, int64_t u, int64_t v, int64_t w);

struct FractalSums {
  int32_t fractal_sum = 0;  // raw SQ2.(10 + X)
  int32_t turbulence = 0;   // raw SQ2.(10 + X), >= 0
};
FractalSums fractal_sums(const NoiseConfig& config, int64_t u, int64_t v, int64_t w);

// The sums as the ports carry them (FractalValue SQ2.14, the default X = 4): from SQ2.(10 + X)
// rounded half up (X > 4) or shifted up (X < 4). The identity at the default widths; the
// materials read this, so that the sweep's other widths keep the same scale.
FractalSums port_sums(const NoiseConfig& config, const FractalSums& sums);

// The raw value of 1.0 in P's format and in the sums' format.
constexpr int32_t noise_one(const NoiseConfig& c) { return int32_t{1} << (7 + c.lerp_extra_bits); }
constexpr int32_t sum_one(const NoiseConfig& c) { return int32_t{1} << (10 + c.lerp_extra_bits); }

}  // namespace tmu::perlin
