// C++ view of the interface format table (formats.def): one fx::Format constant per
// format, one fx::Fixed alias per format, and the shared constants (constants.hpp).
#pragma once

#include <string>

#include "fixed/fixed.hpp"
#include "formats/constants.hpp"

namespace tmu::formats {

#define TMU_FORMAT(name, sv_name, is_signed, int_bits, frac_bits, doc) \
  inline constexpr fx::Format k##name{is_signed != 0, int_bits, frac_bits};
#define TMU_CONST(name, value, doc)
#include "formats/formats.def"
#undef TMU_FORMAT
#undef TMU_CONST

#define TMU_FORMAT(name, sv_name, is_signed, int_bits, frac_bits, doc) \
  using name = fx::Fixed<k##name>;
#define TMU_CONST(name, value, doc)
#include "formats/formats.def"
#undef TMU_FORMAT
#undef TMU_CONST

// The SystemVerilog package generated from the same table (rtl/tmu_pkg.sv).
std::string sv_package();

}  // namespace tmu::formats
