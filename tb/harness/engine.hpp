// One model level of a block (golden, hls or rtl) behind one interface, so the scoreboard
// compares any two of them the same way.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/txn.hpp"

namespace tmu::tb {

// Random back-pressure: before presenting each new input item the driver idles for a cycle
// with probability in_idle (repeatedly), and each cycle it lowers the output ready with
// probability out_stall. Both come from one seeded generator, so a run is reproducible.
struct StallOptions {
  uint64_t seed = 1;
  double in_idle = 0.0;
  double out_stall = 0.0;
};

// Dump an FST waveform of the cycles [begin, end] (rtl only).
struct TraceOptions {
  std::string fst_path;
  uint64_t begin_cycle = 0;
  uint64_t end_cycle = UINT64_MAX;
};

struct RunOptions {
  StallOptions stalls;
  uint64_t x_seed = 1;  // rtl: seed of --x-initial unique / randomized reset values
  std::optional<TraceOptions> trace;
  uint64_t max_idle_cycles = 100000;  // no handshake for this long = deadlock
  // Called now and then with the number of outputs so far (long runs show progress).
  std::function<void(uint64_t outputs)> progress;
};

using Counters = std::vector<std::pair<std::string, uint64_t>>;

// The value of a named counter, if the run reported it.
inline std::optional<uint64_t> counter_value(const Counters& counters, const std::string& name) {
  for (const auto& [n, v] : counters) {
    if (n == name) return v;
  }
  return std::nullopt;
}

struct RunResult {
  std::vector<Txn> outputs;             // in the order they left the block
  std::vector<uint64_t> output_cycles;  // clock cycle of each output (0 for untimed golden)
  std::vector<size_t> output_items;     // input item of each output, where the engine knows it
                                        // (a golden model whose items make several outputs)
  uint64_t cycles = 0;                  // clock cycles of the run (0 for untimed golden)
  Counters counters;                    // the block's statistics registers at the end
  // Every request the block made of its environment, per memory request channel (in the
  // order of BlockPorts::request_channels()), in the order they were made.
  std::vector<std::vector<Txn>> requests;
  double seconds = 0.0;  // wall time of the model alone
  std::string error;     // non-empty when the run could not complete
};

class Engine {
 public:
  virtual ~Engine() = default;
  virtual std::string name() const = 0;
  virtual RunResult run(const std::vector<Txn>& items, const RunOptions& options) = 0;
};

}  // namespace tmu::tb
