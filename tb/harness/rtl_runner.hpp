// Runs a Verilated block through the shared cycle loop (harness/cycle_loop.hpp): random
// initial values (--x-initial unique with a seed), assertions that fail the run, and an
// optional FST window for debugging.
//
// A block plugs in with an RtlAdapter that maps transactions onto its ports (the generic one
// of harness/rtl_ports.hpp, from the block's port description). The runner requires only
// clk_i and rst_ni (active-low, synchronous) on the model; a combinational block has neither.
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>
#if defined(VM_COVERAGE) && VM_COVERAGE
#include <unistd.h>
#include <verilated_cov.h>

#include <atomic>
#include <cstdlib>
#endif

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/cycle_loop.hpp"
#include "harness/engine.hpp"

namespace tmu::tb {

// Adds `error` to the run's error message (runs can fail in more than one way).
inline void append_error(RunResult& result, const std::string& error) {
  if (!error.empty()) result.error += (result.error.empty() ? "" : "; ") + error;
}

template <class Model>
class RtlAdapter {
 public:
  virtual ~RtlAdapter() = default;
  // Once, before reset: the model's inputs to a defined state.
  virtual void init(Model&) {}
  // Present `item` on its input channel (valid high), or nothing (every valid low).
  virtual void drive(Model& m, const Txn* item) = 0;
  // The channel of the presented item is ready (read after eval, before the edge).
  virtual bool accepts(const Model& m, const Txn& item) const = 0;
  virtual void set_out_ready(Model& m, bool ready) = 0;
  virtual bool out_valid(const Model& m) const = 0;
  virtual Txn out(const Model& m) const = 0;
  // A configuration item: the cfg ports and the environment.
  virtual void configure(Model&, const Txn&) {}
  // The block's environment, e.g. a memory model: drive its inputs before eval, sample its
  // requests before the edge.
  virtual void env_drive(Model&) {}
  virtual void env_sample(const Model&) {}
  // Nothing in flight between the block and its environment.
  virtual bool quiet(const Model&) const { return true; }
  // A protocol or address error the environment saw; non-empty fails the run.
  virtual std::string env_error() const { return {}; }
  virtual Counters counters(const Model&) const { return {}; }
  // The end of the run: counters, requests and errors into the result.
  virtual void finish(const Model& m, RunResult& result) {
    result.counters = counters(m);
    append_error(result, env_error());
  }
};

inline constexpr uint64_t kTimePerCycle = 10;  // waveform time units (ns) per clock

// Verilator rejects seed 0; map any 64-bit seed onto 1..2^31-1.
inline int verilator_seed(uint64_t seed) { return static_cast<int>(1 + seed % 0x7FFFFFFEull); }

#if defined(VM_COVERAGE) && VM_COVERAGE
// Coverage build only (-DTMU_RTL_COVERAGE=ON, docs/coverage.md). The coverage files of a
// run, $TMU_COVERAGE_DIR/<pid>_<n> without the extension: unique in the process (one counter
// for every model type) and among processes; empty when the variable is not set.
inline std::string coverage_file() {
  static std::atomic<int> runs{0};
  const char* dir = std::getenv("TMU_COVERAGE_DIR");
  if (dir == nullptr || *dir == '\0') return {};
  return std::string(dir) + "/" + std::to_string(::getpid()) + "_" + std::to_string(runs++);
}
#endif

// Whether a Verilated model has a clock (a combinational top has none).
template <class Model>
concept Clocked = requires(Model m) {
  m.clk_i = 1;
};

// Verilated with --trace-fst (every model but the mutants).
template <class Model>
concept Traced = requires(Model m, VerilatedFstC* fst) {
  m.trace(fst, 99);
};

// A Verilated model as the cycle loop's Sim.
template <class Model>
class RtlSim {
 public:
  RtlSim(RtlAdapter<Model>& adapter, const RunOptions& options)
      : adapter_(adapter), trace_(options.trace ? &*options.trace : nullptr) {
    ctx_ = std::make_unique<VerilatedContext>();
    ctx_->randReset(2);  // every flop and memory starts random: reset bugs show up as X leaks
    ctx_->randSeed(verilator_seed(options.x_seed));
    ctx_->fatalOnError(false);  // a failed assertion fails this run, not the whole process
    if (trace_) ctx_->traceEverOn(true);
    m_ = std::make_unique<Model>(ctx_.get(), "TOP");
    if (trace_) {
      fst_ = std::make_unique<VerilatedFstC>();
      if constexpr (Traced<Model>) {
        m_->trace(fst_.get(), 99);
      } else {
        throw std::runtime_error(
            "this model was built without waveforms (rtl/CMakeLists.txt: "
            "the mutants are)");
      }
    }
    if constexpr (Clocked<Model>) m_->clk_i = 0;
    adapter_.init(*m_);
  }
  ~RtlSim() {
    if (fst_ && fst_->isOpen()) fst_->close();
    m_->final();
  }

  void set_reset(bool active) {
    if constexpr (Clocked<Model>) m_->rst_ni = !active;
  }
  void present(const Txn* item) { adapter_.drive(*m_, item); }
  void configure(const Txn& item) { adapter_.configure(*m_, item); }
  void set_out_ready(bool ready) { adapter_.set_out_ready(*m_, ready); }
  void env_drive() { adapter_.env_drive(*m_); }
  void settle() { m_->eval(); }
  bool accepts(const Txn& item) const { return adapter_.accepts(*m_, item); }
  bool out_valid() const { return adapter_.out_valid(*m_); }
  Txn out() const { return adapter_.out(*m_); }
  void env_sample() { adapter_.env_sample(*m_); }
  bool quiet() const { return adapter_.quiet(*m_); }
  void clock() {
    dump(wave_cycle_ * kTimePerCycle);
    ctx_->time(wave_cycle_ * kTimePerCycle + kTimePerCycle / 2);  // assertion messages show it
    if constexpr (Clocked<Model>) {
      m_->clk_i = 1;
      m_->eval();
    }
    if (ctx_->gotError()) {
      throw std::runtime_error("RTL assertion failed at cycle " +
                               std::to_string(static_cast<int64_t>(wave_cycle_) - kResetCycles) +
                               " (Verilator's %Error line above names it)");
    }
    dump(wave_cycle_ * kTimePerCycle + kTimePerCycle / 2);
    if constexpr (Clocked<Model>) m_->clk_i = 0;
    ++wave_cycle_;
  }
  void finish(RunResult& result) { adapter_.finish(*m_, result); }

#if defined(VM_COVERAGE) && VM_COVERAGE
  // Coverage build: the initialisation and reset go to a file of their own (<file>_reset.dat),
  // then the counters restart. scripts/coverage.sh counts their lines (constant tables, logic
  // fed by the static configuration only settle there), not their toggles (every flop changes
  // from its random initial value into reset). Per instance: scripts/coverage.sh judges a
  // bit's toggles in each instance on its own.
  void coverage_begin() {
    path_ = coverage_file();
    if (path_.empty()) return;
    ctx_->coveragep()->forcePerInstance(true);
    ctx_->coveragep()->write((path_ + "_reset.dat").c_str());
    ctx_->coveragep()->zero();
  }
  // The counters live in this run's context: each run writes its own file (texsim runs
  // several models in one process); scripts/coverage.sh merges them.
  void coverage_end() {
    if (!path_.empty()) ctx_->coveragep()->write((path_ + ".dat").c_str());
  }
#else
  void coverage_begin() {}
  void coverage_end() {}
#endif

 private:
  // The window in the driver's cycles, which are negative during reset; compared unsigned,
  // so that end_cycle's default (UINT64_MAX, the whole run) means what it says.
  void dump(uint64_t time) {
    if (!fst_) return;
    const int64_t c = static_cast<int64_t>(wave_cycle_) - kResetCycles;
    const bool in_window = (c < 0 || static_cast<uint64_t>(c) <= trace_->end_cycle) &&
                           wave_cycle_ >= trace_->begin_cycle;
    if (in_window && !fst_->isOpen()) fst_->open(trace_->fst_path.c_str());
    if (in_window) fst_->dump(time);
    if (!in_window && fst_->isOpen()) fst_->close();
  }

  RtlAdapter<Model>& adapter_;
  const TraceOptions* trace_;
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Model> m_;
  std::unique_ptr<VerilatedFstC> fst_;
  uint64_t wave_cycle_ = 0;  // counts reset cycles too
#if defined(VM_COVERAGE) && VM_COVERAGE
  std::string path_;
#endif
};

template <class Model>
RunResult run_rtl(RtlAdapter<Model>& adapter, const std::vector<Txn>& items, ItemPlan plan,
                  const RunOptions& options) {
  RtlSim<Model> sim(adapter, options);
  HandshakeDriver driver(items, std::move(plan), options);
  RunResult& result = driver.result();
  const auto start = std::chrono::steady_clock::now();
  try {
    run_reset(sim);
    sim.coverage_begin();
    run_items(sim, driver);
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cycles = driver.cycle();
  sim.finish(result);
  sim.coverage_end();
  return std::move(result);
}

// Blocks whose items carry no configuration: only the total of outputs matters.
template <class Model>
RunResult run_rtl(RtlAdapter<Model>& adapter, const std::vector<Txn>& items,
                  size_t expected_outputs, const RunOptions& options) {
  return run_rtl(adapter, items, ItemPlan::without_config(items.size(), expected_outputs), options);
}

}  // namespace tmu::tb
