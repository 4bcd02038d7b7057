// What defines the noise, as data: the lattice's width, the lattice values' width, the
// coordinates' fraction, the octave count and the rows of the scramble T (noise.hpp gives the
// hash they define and why). Definitions only, no arithmetic: golden (noise.hpp) and the
// ideal model (noise_ideal.hpp) each compute the hash from these by their own code, and
// tests/perlin_test.cpp checks that the two agree.
//
// The definition, in short: bit j of T(x) is the parity of x & kXorRows[j] (a 12 x 12 matrix
// over GF(2), invertible); R(x1, x2, x3) = the top kLatticeValueBits of
//   h = T((T((T((T(x1) + x2) mod 2^12) + x3) mod 2^12) + x3) mod 2^12)
// as a signed SQ0.7 number, with x1, x2, x3 the lattice indices mod 2^12.
#pragma once

#include <array>
#include <cstdint>

#include "formats/constants.hpp"

namespace tmu::perlin {

constexpr int kLatticeBits = 12;  // hash width: the lattice repeats every 4096 units
constexpr int kLatticeValueBits = 8;
constexpr int kCoordFracBits = 12;  // SolidCoord's fraction
constexpr int kOctaves = 4;
// T's rows, declared once in formats.def (the RTL reads them from tmu_pkg).
constexpr std::array<uint32_t, kLatticeBits> kXorRows = {
    formats::kNoiseXorRow0, formats::kNoiseXorRow1,  formats::kNoiseXorRow2,
    formats::kNoiseXorRow3, formats::kNoiseXorRow4,  formats::kNoiseXorRow5,
    formats::kNoiseXorRow6, formats::kNoiseXorRow7,  formats::kNoiseXorRow8,
    formats::kNoiseXorRow9, formats::kNoiseXorRow10, formats::kNoiseXorRow11};

}  // namespace tmu::perlin
