// The timed levels of a described block: the rtl engine of any Verilated model with its ports
// (its top, a parameter variant, a mutant) and the hls engine of its SystemC module, each
// driven through the block's port description, with the block's environment and item plan.
#pragma once

#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include "harness/described_block.hpp"
#include "harness/rtl_ports.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

// Desc is the block's description struct (TMU_DESCRIBE: table(), rtl_rows<M>()).
template <class Desc, class M>
class PortsRtlEngine : public Engine {
 public:
  PortsRtlEngine(std::shared_ptr<const DescribedBlock> block, std::string name)
      : block_(std::move(block)), name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    PortLogic<RtlPorts> ports(Desc::table(), Desc::template rtl_rows<M>(),
                              block_->environment(options.stalls.seed ^ kEnvironmentSeedSalt));
    return run_rtl(ports, &make_rtl_model<M>, items, block_->plan(items), options);
  }

 private:
  std::shared_ptr<const DescribedBlock> block_;
  std::string name_;
};

// The factory of an rtl level running model M.
template <class Desc, class M>
DescribedBlock::EngineFactory rtl_level(std::string name) {
  return [name](const DescribedBlock& b) -> std::unique_ptr<Engine> {
    return std::make_unique<PortsRtlEngine<Desc, M>>(b.share(), name);
  };
}

// The icarus level: the RTL top under Icarus Verilog (with these Verilog parameters, "NAME=VALUE
// ..."), in the testbench generated from the block's ports (tb/icarus/testbench.hpp).
DescribedBlock::EngineFactory icarus_level(const std::string& top, const std::string& params);
// Whether the generated Icarus testbench can drive the block (stream channels only).
bool icarus_drives(const BlockPorts& ports);

}  // namespace tmu::tb

// In a described block's constructor: registers the rtl levels of its variant `variant` from
// the block's generated model table (rtl/blocks.cmake: TMU_RTL_MODELS_<block>, in
// <rtl_models_<block>.hpp>), and the icarus level of its rtl top where the testbench drives it.
#define TMU_ADD_RTL_LEVELS(block, variant)        \
  do {                                            \
    const std::string tmu_variant_ = (variant);   \
    TMU_RTL_MODELS_##block(TMU_ADD_RTL_LEVEL_ROW) \
  } while (0)
#define TMU_ADD_RTL_LEVEL_ROW(block, key, level, Model, top, params, options)     \
  if (tmu_variant_ == key) {                                                      \
    add_level(level, ::tmu::tb::rtl_level<::tmu::tb::desc::block, Model>(level)); \
    if (std::string(level) == "rtl" && ::tmu::tb::icarus_drives(port_table()))    \
      add_level("icarus", ::tmu::tb::icarus_level(top, params));                  \
  }
