// `texsim cosim BLOCK`: golden vs hls vs rtl, bit for bit, under random back-pressure.
#include <fmt/format.h>

#include <iostream>

#include "blocks/registry.hpp"
#include "harness/cosim.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {

void add_cosim_command(CLI::App& app, ExitCode& exit_code) {
  std::string blocks_help =
      "Co-simulate a block: the same stimulus through golden, hls and rtl, every\n"
      "output compared bit for bit. Exits 0 only when all transactions match.\nBlocks:\n";
  for (const auto& b : tb::block_list())
    blocks_help += fmt::format("  {:<14} {}\n", b.name, b.summary);
  auto* cmd = app.add_subcommand("cosim", blocks_help);
  struct Args {
    std::string block;
    tb::CosimOptions cosim;
    tb::BlockOptions block_options;
    std::string engines = "hls,rtl";
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("block", args->block, "Block to co-simulate")->required();
  cmd->add_option("--seed", args->cosim.seed, "Seed of the random stimulus and stalls")
      ->capture_default_str();
  cmd->add_option("--count", args->cosim.count, "Random transactions after the directed ones")
      ->capture_default_str();
  cmd->add_option("--engines", args->engines,
                  "Engines compared against golden (comma separated: hls, rtl)")
      ->capture_default_str();
  cmd->add_option("--vectors", args->cosim.vectors_in,
                  "Replay a vector file (CSV) instead of directed + random")
      ->check(CLI::ExistingFile);
  cmd->add_option("--save-vectors", args->cosim.vectors_out,
                  "Write the stimulus that was run to a vector file");
  cmd->add_flag(
      "--no-directed", [args](int64_t) { args->cosim.directed = false; },
      "Skip the directed vectors");
  cmd->add_option("--in-idle", args->cosim.in_idle,
                  "Probability of an idle cycle before each input item")
      ->check(CLI::Range(0.0, 0.95))
      ->capture_default_str();
  cmd->add_option("--out-stall", args->cosim.out_stall,
                  "Probability of output ready low in a cycle")
      ->check(CLI::Range(0.0, 0.95))
      ->capture_default_str();
  cmd->add_flag(
      "--no-x-check", [args](int64_t) { args->cosim.x_check = false; },
      "Skip the second rtl run with other random initial values");
  cmd->add_option("--wave-dir", args->cosim.wave_dir,
                  "Where a mismatch waveform (FST + GTKWave file) goes")
      ->capture_default_str();
  cmd->add_option("--wave-before", args->cosim.wave_before,
                  "Cycles of waveform before the mismatch")
      ->capture_default_str();
  cmd->add_option("--wave-after", args->cosim.wave_after, "Cycles of waveform after the mismatch")
      ->capture_default_str();
  cmd->add_option("--inject-fault", args->cosim.inject_fault,
                  "Flip one bit of output N of every engine, to see the scoreboard catch it");
  cmd->add_option("--texture", args->block_options.texture,
                  "ccc-bilinear: texture (.ccc) instead of a random one")
      ->check(CLI::ExistingFile);
  cmd->add_flag(
      "--no-lookahead", [args](int64_t) { args->block_options.lookahead = false; },
      "ccc-bilinear: disable the neighbour prefetch");
  cmd->callback([args, &exit_code] {
    args->cosim.engines.clear();
    std::stringstream ss(args->engines);
    for (std::string e; std::getline(ss, e, ',');) {
      if (e != "hls" && e != "rtl")
        throw CLI::ValidationError("--engines", "unknown engine '" + e + "'");
      args->cosim.engines.push_back(e);
    }
    args->block_options.seed = args->cosim.seed;
    const auto block = tb::make_block(args->block, args->block_options);
    const tb::CosimResult r = tb::run_cosim(*block, args->cosim, std::cout);
    exit_code.value = r.pass ? 0 : 1;
  });
}

}  // namespace tmu::texsim
