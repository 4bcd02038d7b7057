// The shared constants of the format table (formats.def's TMU_CONST rows) as C++ constants,
// without the formats and their fixed-point types (formats.hpp, which includes this file): a
// definition only, no arithmetic, so that the ideal models can read a constant the hardware
// shares (the noise hash's rows) without sharing golden's arithmetic.
#pragma once

namespace tmu::formats {

#define TMU_FORMAT(name, sv_name, is_signed, int_bits, frac_bits, doc)
#define TMU_CONST(name, value, doc) inline constexpr int k##name = value;
#include "formats/formats.def"
#undef TMU_FORMAT
#undef TMU_CONST

}  // namespace tmu::formats
