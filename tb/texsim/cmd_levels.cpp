// `texsim levels`: the model-level table (model_levels.hpp) for chosen blocks, and on request
// a scene rendered at every engine.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "blocks/registry.hpp"
#include "common/oiio_plugin.hpp"
#include "texsim/commands.hpp"
#include "texsim/model_levels.hpp"

namespace tmu::texsim {

void add_levels_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "levels",
      "What fidelity costs: one workload through every model level of each block, ideal\n"
      "(double), golden (bit-accurate C++), hls (SystemC), rtl (Verilator, one thread), rtl with\n"
      "FST tracing of every signal, rtl verilated with --threads 2, and Icarus Verilog where it\n"
      "accepts the block: transactions per second, the ratio to golden, and whether each level's\n"
      "outputs equal golden's bit for bit (exit 1 when one does not). A level a block lacks shows\n"
      "why. --scene also renders a scene at ideal, golden, hls and rtl and gives each wall time.");
  struct Args {
    std::vector<std::string> blocks = kLevelBlocks;
    size_t count = 50000;
    uint64_t seed = 1;
    std::string scene, out_dir = "out/levels", markdown;
    int64_t inject_fault = -1;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("blocks", args->blocks, "Blocks (default: those with every level built)")
      ->check(CLI::Validator(
          [](const std::string& name) {
            if (!tb::block_name(name).empty()) return std::string();
            std::string known;
            for (const auto& b : tb::block_list()) known += (known.empty() ? "" : ", ") + b.name;
            return "unknown block '" + name + "' (blocks: " + known + ")";
          },
          "BLOCK"))
      ->capture_default_str();
  cmd->add_option("--count", args->count, "Random items per block")
      ->check(CLI::Range(size_t{1}, size_t{100'000'000}))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the stimulus")->capture_default_str();
  cmd->add_option("--scene", args->scene, "Also render this scene at every engine")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out_dir, "The scene renders go here")->capture_default_str();
  cmd->add_option("--inject-fault", args->inject_fault,
                  "Flip bit 0 of this output of every level but golden (shows a mismatch is "
                  "caught)");
  cmd->add_option("--markdown", args->markdown, "Also write the blocks' table as Markdown here");
  cmd->callback([args, &exit_code] {
    if (!args->scene.empty()) load_oiio_plugin();  // before the first render's clock starts
    std::vector<BlockLevels> results;
    for (const std::string& name : args->blocks) {
      const std::string block = tb::block_name(name);
      fmt::print("{}:\n", block);
      results.push_back(
          measure_levels(block, args->count, args->seed, std::cout, args->inject_fault));
      fmt::print("  workload: {}\n", results.back().workload);
      for (const LevelRun& r : results.back().runs) {
        if (r.verdict.starts_with("NO")) exit_code.value = 1;
      }
    }
    levels_table(results).print(args->markdown);
    if (!args->scene.empty()) {
      const auto scene = measure_scene_levels(args->scene, args->out_dir, std::cout);
      scene_levels_table(scene).print("");
    }
  });
}

}  // namespace tmu::texsim
