// Generates the SystemVerilog package from formats.def, so the RTL sees the same widths.
#include <sstream>
#include <string>

#include "formats/formats.hpp"

namespace tmu::formats {
namespace {

// Name -> <Name>W and <Name>Frac parameters and the <sv_name>_t type.
void emit_format(std::ostringstream& out, const char* name, const char* sv_name, bool is_signed,
                 int int_bits, int frac_bits, const char* doc) {
  const fx::Format f{is_signed, int_bits, frac_bits};
  out << "  // " << name << ": " << fx::to_string(f) << ", " << doc << "\n";
  out << "  localparam int unsigned " << name << "W = " << f.width() << ";\n";
  out << "  localparam int unsigned " << name << "Frac = " << frac_bits << ";\n";
  out << "  typedef logic " << (is_signed ? "signed " : "") << "[" << name << "W-1:0] " << sv_name
      << "_t;\n\n";
}

}  // namespace

std::string sv_package() {
  std::ostringstream out;
  out << "// GENERATED from golden/formats/formats.def at configure time (also: texsim formats).\n"
         "// Do not edit: change the table and regenerate (cmake --build build --target "
         "update-formats).\n"
         "package tmu_pkg;\n\n"
         "  // The package declares the formats of every block; each block uses a few.\n"
         "  // verilator lint_off UNUSEDPARAM\n\n";
#define TMU_FORMAT(name, sv_name, is_signed, int_bits, frac_bits, doc) \
  emit_format(out, #name, #sv_name, is_signed != 0, int_bits, frac_bits, doc);
#define TMU_CONST(name, value, doc) \
  out << "  // " << doc << "\n  localparam int unsigned " #name " = " << (value) << ";\n\n";
#include "formats/formats.def"
#undef TMU_FORMAT
#undef TMU_CONST
  out << "  // verilator lint_on UNUSEDPARAM\n\nendpackage\n";
  return out.str();
}

}  // namespace tmu::formats
