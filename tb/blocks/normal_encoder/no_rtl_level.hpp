// The rtl level of a block whose options select widths no variant of rtl/blocks.cmake
// verilates (normal_encoder, coord_gen): golden, hls and icarus (the widths as the RTL's
// parameters) run them, the rtl level says which widths it has.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "blocks/registry.hpp"
#include "harness/described_block.hpp"

namespace tmu::tb {

// A level whose engine is an std::invalid_argument naming the block's verilated variants;
// `options` are the `texsim cosim` options of the widths asked for.
inline DescribedBlock::EngineFactory no_rtl_level(const std::string& block,
                                                  const std::string& options) {
  std::string verilated;
  for (const BlockVariant& v : block_variants()) {
    if (v.block != block) continue;
    verilated += (verilated.empty() ? "" : ", ") + (v.options.empty() ? "the default" : v.options);
  }
  const std::string message = block + ": no rtl model for " + options +
                              " (verilated: " + verilated + "; add a variant to rtl/blocks.cmake)";
  return [message](const DescribedBlock&) -> std::unique_ptr<Engine> {
    throw std::invalid_argument(message);
  };
}

}  // namespace tmu::tb
