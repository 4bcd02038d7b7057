// Runs a SystemC (hls) block under the HandshakeDriver.
//
// SystemC allows one elaboration per process, so every hls run happens in a forked child
// that elaborates, simulates and sends its RunResult back through a pipe. Any number of hls
// runs can then share one texsim or test process.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <systemc>
#include <vector>

#include "harness/engine.hpp"
#include "harness/handshake_driver.hpp"

namespace tmu::tb {

// The SystemC counterpart of RtlAdapter: a module that owns the DUT and its signals.
class ScAdapter {
 public:
  virtual ~ScAdapter() = default;
  virtual void drive(const Txn* item) = 0;
  virtual bool accepts(const Txn& item) const = 0;
  virtual void set_out_ready(bool ready) = 0;
  virtual bool out_valid() const = 0;
  virtual Txn out() const = 0;
  virtual void env_drive() {}
  virtual void env_sample() {}
  // A protocol or address error the environment saw; non-empty fails the run.
  virtual std::string env_error() const { return {}; }
  virtual Counters counters() const { return {}; }
};

// Runs fn in a forked child and returns its result; a crash of the child becomes an error.
RunResult run_in_child(const std::function<RunResult()>& fn);

// Clocks the adapter's DUT. A value written before an edge is what the other side samples at
// that edge, and a signal read right after wait() still holds its pre-edge value, so both
// sides agree on which handshakes fired.
class ScDriver : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(ScDriver);
  ScDriver(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
           ScAdapter& adapter, const std::vector<Txn>& items, size_t expected_outputs,
           const RunOptions& options)
      : sc_module(name),
        rst_n_(rst_n),
        adapter_(adapter),
        driver_(items, expected_outputs, options) {
    SC_THREAD(run);
    sensitive << clk.posedge_event();
    clk_ = &clk;
  }

  RunResult& result() { return driver_.result(); }

 private:
  void wait_edge() { wait(clk_->posedge_event()); }
  void cycle() {
    const Txn* item = driver_.begin_cycle();
    adapter_.drive(item);
    adapter_.set_out_ready(driver_.out_ready());
    adapter_.env_drive();
    wait_edge();
    const bool in_fire = item != nullptr && adapter_.accepts(*item);
    const bool out_fire = driver_.out_ready() && adapter_.out_valid();
    const Txn out = out_fire ? adapter_.out() : Txn{};
    adapter_.env_sample();
    driver_.end_cycle(in_fire, out_fire ? &out : nullptr);
  }
  void run() {
    rst_n_.write(false);
    adapter_.drive(nullptr);
    adapter_.set_out_ready(false);
    for (int i = 0; i < 5; ++i) wait_edge();
    rst_n_.write(true);
    const auto start = std::chrono::steady_clock::now();
    RunResult& result = driver_.result();
    try {
      while (!driver_.done()) cycle();
      for (int i = 0; i < kDrainCycles; ++i) cycle();
    } catch (const std::exception& e) {
      result.error = e.what();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.cycles = driver_.cycle();
    result.counters = adapter_.counters();
    if (const std::string env = adapter_.env_error(); !env.empty()) {
      result.error += (result.error.empty() ? "" : "; ") + env;
    }
    sc_core::sc_stop();
  }

  sc_core::sc_clock* clk_;
  sc_core::sc_signal<bool>& rst_n_;
  ScAdapter& adapter_;
  HandshakeDriver driver_;
};

// Elaborates `make_bench(clk, rst_n)` (the DUT with its adapter) in a child process and runs it.
template <class Bench>
RunResult run_hls(
    const std::function<std::unique_ptr<Bench>(sc_core::sc_clock&, sc_core::sc_signal<bool>&)>&
        make_bench,
    const std::vector<Txn>& items, size_t expected_outputs, const RunOptions& options) {
  return run_in_child([&]() -> RunResult {
    sc_core::sc_clock clk("clk", 10, sc_core::SC_NS);
    sc_core::sc_signal<bool> rst_n("rst_n");
    std::unique_ptr<Bench> bench = make_bench(clk, rst_n);
    ScDriver driver("driver", clk, rst_n, *bench, items, expected_outputs, options);
    sc_core::sc_start();
    return std::move(driver.result());
  });
}

}  // namespace tmu::tb
