// texsim: the user's entry point to the texture-mapping unit models.
// Exit codes: 0 success (every comparison matched), 1 a model disagreed, 2 bad input or argument.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>

#include "common/error.hpp"
#include "texsim/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "texsim: bit-accurate golden, SystemC (hls) and Verilated RTL models of a texture-mapping "
      "unit, co-simulated and compared bit for bit."};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");
  tmu::texsim::ExitCode exit_code;
  tmu::texsim::add_render_command(app, exit_code);
  tmu::texsim::add_cosim_command(app, exit_code);
  tmu::texsim::add_ccc_command(app, exit_code);
  tmu::texsim::add_mipgen_command(app, exit_code);
  tmu::texsim::add_sample_command(app, exit_code);
  tmu::texsim::add_sweep_command(app, exit_code);
  tmu::texsim::add_levels_command(app, exit_code);
  tmu::texsim::add_pattern_command(app, exit_code);
  tmu::texsim::add_terrain_command(app, exit_code);
  tmu::texsim::add_volume_gen_command(app, exit_code);
  tmu::texsim::add_nurbs_command(app, exit_code);
  tmu::texsim::add_drf_command(app, exit_code);
  tmu::texsim::add_regress_command(app, exit_code);
  tmu::texsim::add_bumpmap_command(app, exit_code);
  tmu::texsim::add_formats_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help prints and exits 0; every bad argument exits 2 like every bad input file.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const tmu::InputError& e) {
    fmt::print(stderr, "texsim: error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "texsim: error: {}\n", e.what());
    return 2;
  }
  return exit_code.value;
}
