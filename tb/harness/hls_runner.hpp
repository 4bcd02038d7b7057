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

#include "harness/cycle_loop.hpp"
#include "harness/engine.hpp"

namespace tmu::tb {

// The SystemC counterpart of a Verilated model and its port logic: a module that owns the DUT
// and its signals.
class ScAdapter {
 public:
  virtual ~ScAdapter() = default;
  virtual void drive(const Txn* item) = 0;
  virtual bool accepts(const Txn& item) const = 0;
  virtual void set_out_ready(bool ready) = 0;
  virtual bool out_valid() const = 0;
  virtual Txn out() const = 0;
  virtual void configure(const Txn&) {}
  virtual void env_drive() {}
  virtual void env_sample() {}
  virtual bool quiet() const { return true; }
  // A protocol or address error the environment saw; non-empty fails the run.
  virtual std::string env_error() const { return {}; }
  virtual Counters counters() const { return {}; }
  // The end of the run: counters, requests and errors into the result.
  virtual void finish(RunResult& result) {
    result.counters = counters();
    if (const std::string e = env_error(); !e.empty()) {
      result.error += (result.error.empty() ? "" : "; ") + e;
    }
  }
};

// Runs fn in a forked child and returns its result; a crash of the child becomes an error.
RunResult run_in_child(const std::function<RunResult()>& fn);

// Clocks the adapter's DUT through the shared cycle loop. A value written before an edge is
// what the other side samples at that edge, and a signal read right after wait() still holds
// its pre-edge value, so both sides agree on which handshakes fired.
class ScDriver : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(ScDriver);
  ScDriver(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
           ScAdapter& adapter, const std::vector<Txn>& items, ItemPlan plan,
           const RunOptions& options)
      : sc_module(name),
        clk_(clk),
        rst_n_(rst_n),
        adapter_(adapter),
        driver_(items, std::move(plan), options) {
    SC_THREAD(run);
    sensitive << clk.posedge_event();
  }

  RunResult& result() { return driver_.result(); }

  // The cycle loop's Sim.
  void set_reset(bool active) { rst_n_.write(!active); }
  void present(const Txn* item) { adapter_.drive(item); }
  void configure(const Txn& item) { adapter_.configure(item); }
  void set_out_ready(bool ready) { adapter_.set_out_ready(ready); }
  void env_drive() { adapter_.env_drive(); }
  void settle() { wait(clk_.posedge_event()); }
  bool accepts(const Txn& item) const { return adapter_.accepts(item); }
  bool out_valid() const { return adapter_.out_valid(); }
  Txn out() const { return adapter_.out(); }
  void env_sample() { adapter_.env_sample(); }
  bool quiet() const { return adapter_.quiet(); }
  void clock() {}

 private:
  void run() {
    const auto start = std::chrono::steady_clock::now();
    RunResult& result = driver_.result();
    try {
      run_reset(*this);
      run_items(*this, driver_);
    } catch (const std::exception& e) {
      result.error = e.what();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.cycles = driver_.cycle();
    adapter_.finish(result);
    sc_core::sc_stop();
  }

  sc_core::sc_clock& clk_;
  sc_core::sc_signal<bool>& rst_n_;
  ScAdapter& adapter_;
  HandshakeDriver driver_;
};

// Elaborates `make_bench(clk, rst_n)` (the DUT with its adapter) in a child process and runs it.
template <class Bench>
RunResult run_hls(
    const std::function<std::unique_ptr<Bench>(sc_core::sc_clock&, sc_core::sc_signal<bool>&)>&
        make_bench,
    const std::vector<Txn>& items, ItemPlan plan, const RunOptions& options);
// Blocks whose items carry no configuration: only the total of outputs matters.
template <class Bench>
RunResult run_hls(
    const std::function<std::unique_ptr<Bench>(sc_core::sc_clock&, sc_core::sc_signal<bool>&)>&
        make_bench,
    const std::vector<Txn>& items, size_t expected_outputs, const RunOptions& options) {
  return run_hls<Bench>(make_bench, items, ItemPlan::without_config(items.size(), expected_outputs),
                        options);
}

template <class Bench>
RunResult run_hls(
    const std::function<std::unique_ptr<Bench>(sc_core::sc_clock&, sc_core::sc_signal<bool>&)>&
        make_bench,
    const std::vector<Txn>& items, ItemPlan plan, const RunOptions& options) {
  return run_in_child([&]() -> RunResult {
    sc_core::sc_clock clk("clk", 10, sc_core::SC_NS);
    sc_core::sc_signal<bool> rst_n("rst_n");
    std::unique_ptr<Bench> bench = make_bench(clk, rst_n);
    ScDriver driver("driver", clk, rst_n, *bench, items, std::move(plan), options);
    sc_core::sc_start();
    return std::move(driver.result());
  });
}

}  // namespace tmu::tb
