// `texsim formats`: the interface format table, and the SystemVerilog package made from it.
#include <fmt/format.h>

#include <memory>

#include "formats/formats.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {

void add_formats_command(CLI::App& app, ExitCode&) {
  auto* cmd =
      app.add_subcommand("formats", "Print the interface formats (golden/formats/formats.def)");
  auto sv = std::make_shared<bool>(false);
  cmd->add_flag("--sv-package", *sv, "Print the generated SystemVerilog package rtl/tmu_pkg.sv");
  cmd->callback([sv] {
    if (*sv) {
      fmt::print("{}", formats::sv_package());
      return;
    }
    fmt::print("{:<16} {:<10} {:>5}  {}\n", "format", "Qm.n", "bits", "meaning");
#define TMU_FORMAT(name, sv_name, is_signed, int_bits, frac_bits, doc)            \
  fmt::print("{:<16} {:<10} {:>5}  {}\n", #name, fx::to_string(formats::k##name), \
             formats::k##name.width(), doc);
#define TMU_CONST(name, value, doc) \
  fmt::print("{:<16} {:<10} {:>5}  {}\n", #name, "const", value, doc);
#include "formats/formats.def"
#undef TMU_FORMAT
#undef TMU_CONST
  });
}

}  // namespace tmu::texsim
