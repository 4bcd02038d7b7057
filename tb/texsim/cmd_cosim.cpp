// `texsim cosim BLOCK`: golden vs hls vs rtl, bit for bit, under random back-pressure.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>

#include "blocks/registry.hpp"
#include "harness/cosim.hpp"
#include "harness/described_block.hpp"
#include "texsim/commands.hpp"
#include "texsim/cosim_options.hpp"

namespace tmu::texsim {

void add_cosim_command(CLI::App& app, ExitCode& exit_code) {
  std::string blocks_help =
      "Co-simulate a block: the same stimulus through golden, hls and rtl, every\n"
      "output compared bit for bit. Exits 0 only when all transactions match.\nBlocks:\n";
  for (const auto& b : tb::block_list()) {
    std::string was;
    for (const std::string& a : b.aliases) was += (was.empty() ? " (was " : ", ") + a;
    blocks_help += fmt::format("  {:<18} {}{}\n", b.name, b.summary, was.empty() ? "" : was + ")");
  }
  auto* cmd = app.add_subcommand("cosim", blocks_help);
  const auto args = add_cosim_options(*cmd);
  cmd->callback([cmd, args, &exit_code] {
    CosimRequest r = finish(*args);
    const auto block = tb::make_block(r.block, r.block_options);
    // Without --engines, the default levels the block has: a block without a SystemC model
    // (bank_address, footprint_setup, material_fire) compares rtl alone, widths without a verilated
    // variant hls alone; a note names what is left out.
    const auto* described = dynamic_cast<const tb::DescribedBlock*>(block.get());
    if (cmd->count("--engines") == 0 && described != nullptr) {
      const std::vector<std::string> have = described->levels();
      std::erase_if(r.cosim.engines, [&](const std::string& e) {
        if (std::find(have.begin(), have.end(), e) != have.end()) return false;
        fmt::print("note: {} has no {} level here (levels: {}): not compared\n", r.block, e,
                   fmt::join(have, ", "));
        return true;
      });
    }
    const tb::CosimResult result = tb::run_cosim(*block, r.cosim, std::cout);
    exit_code.value = result.pass ? 0 : 1;
  });
}

}  // namespace tmu::texsim
