// Runs a Verilated block through the shared cycle loop (harness/cycle_loop.hpp): random
// initial values (--x-initial unique with a seed), assertions that fail the run, and an
// optional FST window for debugging.
//
// A block plugs in with the port logic of its port description (harness/port_logic.hpp, the
// accessors from harness/rtl_ports.hpp) and the factory of its model (harness/rtl_model.hpp). The
// runner requires only clk_i and rst_ni (active-low, synchronous) on the model; a combinational
// block has neither.
#pragma once

#include <vector>

#include "harness/cycle_loop.hpp"
#include "harness/engine.hpp"
#include "harness/port_logic.hpp"
#include "harness/rtl_model.hpp"

namespace tmu::tb {

inline constexpr uint64_t kTimePerCycle = 10;  // waveform time units (ns) per clock

// Compiled once, in rtl_runner.cpp.
extern template class PortLogic<RtlPorts>;

// Runs `items` on a new model from `model`, driven and sampled through `ports`.
RunResult run_rtl(PortLogic<RtlPorts>& ports, RtlModelFactory model, const std::vector<Txn>& items,
                  ItemPlan plan, const RunOptions& options);

}  // namespace tmu::tb
