// The cycle-by-cycle stimulus logic shared by every timed runner (rtl, hls): which input
// item is presented, whether the output is ready, what fired at the edge.
//
// Rules: items are presented strictly in order, one at a time; a presented item stays
// presented (valid held high, data stable) until its channel accepts it; bubbles and output
// stalls are drawn from the seeded generator. A configuration item is not presented on a
// channel: the driver waits until the block is quiet (every output of the earlier items out,
// nothing outstanding, for kQuietCycles cycles), then the runner writes it to the cfg ports in
// one cycle, as a driver between two batches would. The driver records every output and fails
// the run on a deadlock (no handshake for max_idle_cycles) or an output beyond the expected
// count (a duplicated transaction).
#pragma once

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/engine.hpp"

namespace tmu::tb {

// What each input item is to the driver: how many outputs it gives, and whether it is a
// configuration item.
struct ItemPlan {
  std::vector<uint32_t> outputs;  // per item
  std::vector<bool> config;       // per item; empty: none is
  size_t total = 0;               // the sum of outputs

  // A plan of `total` outputs over items of which none is a configuration item (the
  // per-item counts do not matter without configuration items).
  static ItemPlan without_config(size_t items, size_t total) {
    ItemPlan p;
    p.outputs.assign(items, 0);
    p.total = total;
    return p;
  }
  bool is_config(size_t item) const { return !config.empty() && config[item]; }
};

// Cycles the runners keep clocking after the last expected output, with the output ready,
// to catch a block that emits more than it was asked for.
inline constexpr int kDrainCycles = 16;
// Quiet cycles before a configuration item is applied.
inline constexpr int kQuietCycles = 8;

class HandshakeDriver {
 public:
  HandshakeDriver(const std::vector<Txn>& items, ItemPlan plan, const RunOptions& options)
      : items_(items), plan_(std::move(plan)), options_(options), rng_(options.stalls.seed) {
    result_.outputs.reserve(plan_.total);
    result_.output_cycles.reserve(plan_.total);
  }

  // Start of a cycle: decide what the inputs show. Returns the item to present (or to
  // configure, when configuring() says so), or nullptr. `quiet`: the block has nothing in
  // flight this cycle (no request outstanding), as its runner sees it.
  const Txn* begin_cycle(bool quiet = true) {
    configuring_ = false;
    if (!presenting_ && next_ < items_.size()) {
      if (plan_.is_config(next_)) {
        quiet_ = quiet && result_.outputs.size() >= outputs_due_ ? quiet_ + 1 : 0;
        configuring_ = quiet_ > kQuietCycles;
      } else {
        presenting_ = !(options_.stalls.in_idle > 0.0 && coin(options_.stalls.in_idle));
      }
    }
    out_ready_ = !(options_.stalls.out_stall > 0.0 && coin(options_.stalls.out_stall));
    return presenting_ || configuring_ ? &items_[next_] : nullptr;
  }
  bool out_ready() const { return out_ready_; }
  // The item of this cycle is a configuration item, written to the cfg ports this cycle.
  bool configuring() const { return configuring_; }

  // After sampling the handshakes before the clock edge: in_fire = the presented item was
  // accepted; out = the output that fired (nullptr if none).
  void end_cycle(bool in_fire, const Txn* out) {
    if (in_fire || configuring_) {
      outputs_due_ += next_ < plan_.outputs.size() ? plan_.outputs[next_] : 0;
      presenting_ = false;
      quiet_ = 0;
      ++next_;
      last_progress_ = cycle_;
    }
    if (out != nullptr) {
      if (result_.outputs.size() >= plan_.total) {
        throw std::runtime_error("output " + std::to_string(result_.outputs.size()) + " at cycle " +
                                 std::to_string(cycle_) + " is beyond the " +
                                 std::to_string(plan_.total) +
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
                               std::to_string(plan_.total) + " outputs)");
    }
  }

  // Every item accepted and every expected output seen.
  bool done() const { return next_ == items_.size() && result_.outputs.size() == plan_.total; }
  uint64_t cycle() const { return cycle_; }
  RunResult& result() { return result_; }

 private:
  static constexpr size_t kProgressEvery = 4096;
  bool coin(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p; }

  const std::vector<Txn>& items_;
  ItemPlan plan_;
  RunOptions options_;
  std::mt19937_64 rng_;
  size_t next_ = 0;
  size_t outputs_due_ = 0;  // outputs of the items accepted so far
  bool presenting_ = false;
  bool configuring_ = false;
  int quiet_ = 0;
  bool out_ready_ = true;
  uint64_t cycle_ = 0;
  uint64_t last_progress_ = 0;
  RunResult result_;
};

}  // namespace tmu::tb
