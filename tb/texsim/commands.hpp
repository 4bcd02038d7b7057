// texsim's subcommands; each registers itself on the CLI11 app and returns its exit code
// through the shared slot.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace tmu::texsim {

// The engines a command that co-simulates a block accepts (--engine).
inline const std::vector<std::string> kCosimEngines{"golden", "hls", "rtl"};

struct ExitCode {
  int value = 0;
};

void add_cosim_command(CLI::App& app, ExitCode& exit_code);
void add_ccc_command(CLI::App& app, ExitCode& exit_code);
void add_formats_command(CLI::App& app, ExitCode& exit_code);
void add_pattern_command(CLI::App& app, ExitCode& exit_code);
void add_terrain_command(CLI::App& app, ExitCode& exit_code);
void add_nurbs_command(CLI::App& app, ExitCode& exit_code);
void add_drf_command(CLI::App& app, ExitCode& exit_code);
void add_regress_command(CLI::App& app, ExitCode& exit_code);
void add_bumpmap_command(CLI::App& app, ExitCode& exit_code);
void add_sample_command(CLI::App& app, ExitCode& exit_code);
void add_mipgen_command(CLI::App& app, ExitCode& exit_code);
void add_sweep_command(CLI::App& app, ExitCode& exit_code);
void add_render_command(CLI::App& app, ExitCode& exit_code);
void add_levels_command(CLI::App& app, ExitCode& exit_code);
void add_volume_gen_command(CLI::App& app, ExitCode& exit_code);

}  // namespace tmu::texsim
