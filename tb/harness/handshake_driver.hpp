// The cycle-by-cycle stimulus logic shared by the rtl (Verilator) and hls (SystemC) runners:
// which input item is presented, whether the output is ready, what fired at the edge.
//
// Rules: items are presented strictly in order, one at a time; a presented item stays
// presented (valid held high, data stable) until its channel accepts it; bubbles and output
// stalls are drawn from the seeded generator. The driver records every output and fails the
// run on a deadlock (no handshake for max_idle_cycles) or an output beyond the expected count
// (a duplicated transaction).
#pragma once

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/engine.hpp"

namespace tmu::tb {

class HandshakeDriver {
 public:
  HandshakeDriver(const std::vector<Txn>& items, size_t expected_outputs, const RunOptions& options)
      : items_(items),
        expected_outputs_(expected_outputs),
        options_(options),
        rng_(options.stalls.seed) {
    result_.outputs.reserve(expected_outputs);
    result_.output_cycles.reserve(expected_outputs);
  }

  // Start of a cycle: decide what the inputs show. Returns the item to present, or nullptr.
  const Txn* begin_cycle() {
    if (!presenting_ && next_ < items_.size()) {
      presenting_ = !(options_.stalls.in_idle > 0.0 && coin(options_.stalls.in_idle));
    }
    out_ready_ = !(options_.stalls.out_stall > 0.0 && coin(options_.stalls.out_stall));
    return presenting_ ? &items_[next_] : nullptr;
  }
  bool out_ready() const { return out_ready_; }

  // After sampling the handshakes before the clock edge: in_fire = the presented item was
  // accepted; out = the output that fired (nullptr if none).
  void end_cycle(bool in_fire, const Txn* out) {
    if (in_fire) {
      presenting_ = false;
      ++next_;
      last_progress_ = cycle_;
    }
    if (out != nullptr) {
      if (result_.outputs.size() >= expected_outputs_) {
        throw std::runtime_error("output " + std::to_string(result_.outputs.size()) + " at cycle " +
                                 std::to_string(cycle_) + " is beyond the " +
                                 std::to_string(expected_outputs_) +
                                 " expected: a transaction was duplicated");
      }
      result_.outputs.push_back(*out);
      result_.output_cycles.push_back(cycle_);
      if (options_.progress && result_.outputs.size() % kProgressEvery == 0)
        options_.progress(result_.outputs.size());
      last_progress_ = cycle_;
    }
    ++cycle_;
    if (cycle_ - last_progress_ > options_.max_idle_cycles) {
      throw std::runtime_error("deadlock: no handshake for " +
                               std::to_string(options_.max_idle_cycles) + " cycles (cycle " +
                               std::to_string(cycle_) + ", " + std::to_string(next_) + " of " +
                               std::to_string(items_.size()) + " items accepted, " +
                               std::to_string(result_.outputs.size()) + " of " +
                               std::to_string(expected_outputs_) + " outputs)");
    }
  }

  // Every item accepted and every expected output seen.
  bool done() const {
    return next_ == items_.size() && result_.outputs.size() == expected_outputs_;
  }
  uint64_t cycle() const { return cycle_; }
  RunResult& result() { return result_; }

 private:
  static constexpr size_t kProgressEvery = 4096;
  bool coin(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p; }

  const std::vector<Txn>& items_;
  size_t expected_outputs_;
  RunOptions options_;
  std::mt19937_64 rng_;
  size_t next_ = 0;
  bool presenting_ = false;
  bool out_ready_ = true;
  uint64_t cycle_ = 0;
  uint64_t last_progress_ = 0;
  RunResult result_;
};

// Cycles the runners keep clocking after the last expected output, with the output ready,
// to catch a block that emits more than it was asked for.
inline constexpr int kDrainCycles = 16;

}  // namespace tmu::tb
