// Runs a Verilated block through the shared cycle loop (harness/cycle_loop.hpp): random
// initial values (--x-initial unique with a seed), assertions that fail the run, and an
// optional FST window for debugging.
//
// A block plugs in with the port logic of its port description (harness/port_logic.hpp, the
// accessors from harness/rtl_ports.hpp) and the factory of its model (harness/rtl_model.hpp). The
// runner requires only clk_i and rst_ni (active-low, synchronous) on the model; a combinational
// block has neither.
#pragma once

#include <string>
#include <vector>

#include "harness/cycle_loop.hpp"
#include "harness/engine.hpp"
#include "harness/port_logic.hpp"
#include "harness/rtl_model.hpp"

namespace tmu::tb {

// Adds `error` to the run's error message (runs can fail in more than one way).
inline void append_error(RunResult& result, const std::string& error) {
  if (!error.empty()) result.error += (result.error.empty() ? "" : "; ") + error;
}

inline constexpr uint64_t kTimePerCycle = 10;  // waveform time units (ns) per clock

// Verilator rejects seed 0; map any 64-bit seed onto 1..2^31-1.
inline int verilator_seed(uint64_t seed) { return static_cast<int>(1 + seed % 0x7FFFFFFEull); }

// Compiled once, in rtl_runner.cpp.
extern template class PortLogic<RtlPorts>;

// Runs `items` on a new model from `model`, driven and sampled through `ports`.
RunResult run_rtl(PortLogic<RtlPorts>& ports, RtlModelFactory model, const std::vector<Txn>& items,
                  ItemPlan plan, const RunOptions& options);

}  // namespace tmu::tb
