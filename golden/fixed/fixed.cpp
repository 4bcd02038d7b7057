#include "fixed/fixed.hpp"

namespace tmu::fx {

std::string to_string(const Format& f) {
  return std::string(f.is_signed ? "SQ" : "UQ") + std::to_string(f.int_bits) + "." +
         std::to_string(f.frac_bits);
}

}  // namespace tmu::fx
