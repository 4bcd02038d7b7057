// The CCC texture and its `.ccc` container (000 §3, Figs. 4-5).
//
// Container, little-endian:
//   offset 0   "CCC1" magic
//   offset 4   u32 width in texels (>= 1)
//   offset 8   u32 height in texels (>= 1)
//   offset 12  256 x 3 bytes CLUT, R G B per entry
//   offset 780 ceil(w/4) * ceil(h/4) u32 block words, row-major
// A block word holds index a in bits 31..24, index b in 23..16 and the decision bits in
// 15..0; bit (4*y + x) set means texel (x, y) of the block takes colour b. Edge blocks cover
// texels beyond the image, padded by repeating the last row / column when encoding.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/image.hpp"

namespace tmu::ccc {

using Clut = std::array<Rgb8, 256>;

struct Block {
  uint8_t a = 0;      // CLUT index of colour a (decision bit 0)
  uint8_t b = 0;      // CLUT index of colour b (decision bit 1)
  uint16_t bits = 0;  // decision bit per texel, bit 4*y + x

  constexpr uint32_t word() const { return (uint32_t{a} << 24) | (uint32_t{b} << 16) | bits; }
  static constexpr Block from_word(uint32_t w) {
    return {static_cast<uint8_t>(w >> 24), static_cast<uint8_t>(w >> 16), static_cast<uint16_t>(w)};
  }
  friend bool operator==(const Block&, const Block&) = default;
};

struct Texture {
  uint32_t width = 0;
  uint32_t height = 0;
  Clut clut{};
  std::vector<uint32_t> blocks;  // block words, row-major

  uint32_t blocks_wide() const { return (width + 3) / 4; }
  uint32_t blocks_high() const { return (height + 3) / 4; }
  uint32_t block_word(uint32_t bx, uint32_t by) const {
    return blocks[size_t{by} * blocks_wide() + bx];
  }
  friend bool operator==(const Texture&, const Texture&) = default;
};

inline constexpr std::string_view kMagic = "CCC1";
inline constexpr size_t kHeaderBytes = 12 + 256 * 3;

// Bytes of the container. Throws std::invalid_argument if the block count is inconsistent.
std::string serialize(const Texture& tex);
// Parses a container; `name` (usually the file path) is used in error messages. Throws
// InputError naming the field that is wrong (magic, width, height, clut, blocks, size).
Texture parse(std::string_view bytes, const std::string& name);

Texture read_ccc(const std::string& path);
void write_ccc(const std::string& path, const Texture& tex);  // atomic

}  // namespace tmu::ccc
