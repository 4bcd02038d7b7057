// How the footprint setup measures the footprint's width q (000 §7): a definition shared by the
// golden setup (footprint.hpp) and its ideal (footprint_ideal.hpp), no arithmetic.
#pragma once

#include <cstdint>

namespace tmu::footprint {

enum class QRule : uint8_t {
  kHeights,  // min(|r1|, |r2|, d1, d2) with d1, d2 the parallelogram's heights
  kSides,    // min(|r1|, |r2|): the text's two surviving terms only
};

}  // namespace tmu::footprint
