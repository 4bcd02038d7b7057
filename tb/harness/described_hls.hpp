// The hls level of a described block: its SystemC module in the bench of its port description
// (harness/sc_ports.hpp), with the block's environment and item plan, in a forked child.
#pragma once

#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include "harness/described_block.hpp"
#include "harness/sc_ports.hpp"

namespace tmu::tb {

// Signals is the block's TMU_DESCRIBE_SC struct, Dut its module, args its constructor's after
// the name.
template <class Signals, class Dut, class... Args>
class PortsHlsEngine : public Engine {
 public:
  PortsHlsEngine(std::shared_ptr<const DescribedBlock> block, Args... args)
      : block_(std::move(block)), args_(std::move(args)...) {}
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    using Bench = PortsScBench<Signals, Dut>;
    const DescribedBlock& b = *block_;
    return run_hls<Bench>(
        [&](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::apply(
              [&](const Args&... a) {
                return std::make_unique<Bench>(
                    "bench", clk, rst_n, b.port_table(),
                    b.environment(options.stalls.seed ^ kEnvironmentSeedSalt), a...);
              },
              args_);
        },
        items, b.plan(items), options);
  }

 private:
  std::shared_ptr<const DescribedBlock> block_;
  std::tuple<Args...> args_;
};

template <class Signals, class Dut, class... Args>
DescribedBlock::EngineFactory hls_level(Args... args) {
  return [=](const DescribedBlock& b) -> std::unique_ptr<Engine> {
    return std::make_unique<PortsHlsEngine<Signals, Dut, Args...>>(b.share(), args...);
  };
}

}  // namespace tmu::tb
