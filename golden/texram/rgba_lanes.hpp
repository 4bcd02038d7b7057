// RGBA8888 colours in SWAR lanes of a 64-bit word: exact per-channel sums and weighted sums
// in a few integer multiplies, for the fast paths (fast_trilinear.hpp, fast_footprint.hpp).
// Every user keeps each lane below its limit (16-bit lanes < 2^16, 32-bit lanes < 2^32), so
// no carry crosses into the next channel; the limits are stated where the sums are made.
#pragma once

#include <cstdint>

namespace tmu::texram {

// Four 16-bit lanes: R in 63:48, G 47:32, B 31:16, A 15:0.
constexpr uint64_t spread16(uint32_t rgba) {
  uint64_t x = rgba;
  x = (x | x << 16) & 0x0000FFFF0000FFFFull;
  return (x | x << 8) & 0x00FF00FF00FF00FFull;
}

// The low byte of each 16-bit lane, packed back to RGBA8888.
constexpr uint32_t pack16(uint64_t lanes) {
  const uint64_t x = lanes & 0x00FF00FF00FF00FFull;
  const uint64_t y = (x | x >> 8) & 0x0000FFFF0000FFFFull;
  return static_cast<uint32_t>(y | y >> 16);
}

// The low halves of two 32-bit lanes: splits a 16-bit-lane word into G, A (this mask) and,
// after >> 16, R, B.
inline constexpr uint64_t kLow32Lanes = 0x0000FFFF0000FFFFull;

// RGBA8888 from the low bytes of two 32-bit-lane words: rb holds R (63:32) and B (31:0), ga
// holds G and A.
constexpr uint32_t pack32(uint64_t rb, uint64_t ga) {
  return static_cast<uint32_t>((rb >> 32 & 0xFF) << 24 | (ga >> 32 & 0xFF) << 16 |
                               (rb & 0xFF) << 8 | (ga & 0xFF));
}

}  // namespace tmu::texram
