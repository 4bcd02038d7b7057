// What a TEXRAM texture was made from, as the host gave it: the input of the ideal models
// (trilinear_ideal.hpp), kept beside the bank image so that no ideal model reads the banks
// through golden's layout or golden's pyramid. A definition only: containers, no arithmetic.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "texram/level8.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::texram {

struct SourceTexels {
  TexelKind kind = TexelKind::kLuminance;
  uint32_t width = 0, height = 0;  // level 0, in texels
  // One pyramid per byte plane (1, or 4 for true colour and CCC), level 0 first.
  //   box_levels: only level 0 is here; the levels above are the box rule of 000 §12 applied to
  //     it (import_image built them so), which the ideal computes exactly for itself.
  //   otherwise every level as the caller gave it (random levels, the palette indices of an
  //     index texture, the CCC blocks of each level: encodings the host chose, not arithmetic
  //     of the chip's).
  std::vector<Pyramid8> planes;
  bool box_levels = false;
  // CCC: the planes are the bytes of the block words (bits 31:24 in plane 0) at block
  // resolution; a texel's colour is the CLUT entry its decision bit picks.
  bool block_grid = false;
  std::array<uint32_t, 256> clut{};  // RGBA8888 (index and CCC textures)
};

}  // namespace tmu::texram
