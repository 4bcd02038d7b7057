// What the detail-map golden model (detail.hpp) and its ideal (detail_ideal.hpp) share: the
// combine rule's name and the shape of the detail mipmap. Definitions only, no arithmetic
// (tests/ideal_independence_test.sh; docs/detail.md lists this file and states every rule).
//
// Shape (000 §9): a texture's level 0 is the top of a detail mipmap with kDetailLevels more
// levels, lambda = -1 .. -4; a level-0 texel covers kDetailRegionSide x kDetailRegionSide texels
// of level -4, its *region*, which starts at the two 8-bit offsets (the texel's entries in the
// u- and v-offset maps) in the detail map, a texture of at most 2^kMaxDetailLog2 texels a side
// whose level l stands for lambda = l - kDetailLevels.
#pragma once

#include <cstdint>

#include "formats/constants.hpp"

namespace tmu::texram {

// How the detail colour D and the texture's level-0 colour T make the sample (formats.def
// TexDetailCombine; the exact arithmetic is in detail.hpp, the real-valued one in
// detail_ideal.hpp).
enum class DetailCombine : uint8_t {
  kReplace = 0,   // the detail levels continue the texture's pyramid: the colour is D
  kModulate = 1,  // D is a grey micro-structure centred at 128: RGB = min(255, T D / 128), A = T's
};

inline constexpr int kDetailRegionSide = formats::kDetailRegionSide;  // 16
inline constexpr int kDetailLevels = formats::kDetailLevels;          // 4
inline constexpr int kMaxDetailLog2 = formats::kMaxDetailLog2;        // 8
static_assert(kDetailRegionSide == 1 << kDetailLevels, "a region is level 0's texel at level -4");

}  // namespace tmu::texram
