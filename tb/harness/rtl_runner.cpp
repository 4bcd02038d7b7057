#include "harness/rtl_runner.hpp"

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
#include <utility>
#include <vector>

namespace tmu::tb {

template class PortLogic<RtlPorts>;

namespace {

// Verilator rejects seed 0; map any 64-bit seed onto 1..2^31-1.
int verilator_seed(uint64_t seed) { return static_cast<int>(1 + seed % 0x7FFFFFFEull); }

#if defined(VM_COVERAGE) && VM_COVERAGE
// Coverage build only (-DTMU_RTL_COVERAGE=ON, docs/coverage.md). The coverage files of a
// run, $TMU_COVERAGE_DIR/<pid>_<n> without the extension: unique in the process (one counter
// for every model) and among processes; empty when the variable is not set.
std::string coverage_file() {
  static std::atomic<int> runs{0};
  const char* dir = std::getenv("TMU_COVERAGE_DIR");
  if (dir == nullptr || *dir == '\0') return {};
  return std::string(dir) + "/" + std::to_string(::getpid()) + "_" + std::to_string(runs++);
}
#endif

// A Verilated model as the cycle loop's Sim.
class RtlSim {
 public:
  RtlSim(PortLogic<RtlPorts>& ports, RtlModelFactory model, const RunOptions& options)
      : ports_(ports), trace_(options.trace ? &*options.trace : nullptr) {
    ctx_ = std::make_unique<VerilatedContext>();
    ctx_->randReset(2);  // every flop and memory starts random: reset bugs show up as X leaks
    ctx_->randSeed(verilator_seed(options.x_seed));
    ctx_->fatalOnError(false);  // a failed assertion fails this run, not the whole process
    if (trace_) ctx_->traceEverOn(true);
    m_ = model(ctx_.get());
    if (trace_) {
      fst_ = std::make_unique<VerilatedFstC>();
      if (!m_->trace(fst_.get())) {
        throw std::runtime_error(
            "this model was built without waveforms (rtl/CMakeLists.txt: "
            "the mutants are)");
      }
    }
    m_->clock_low();
    ports_.init(p());
  }
  ~RtlSim() {
    if (fst_ && fst_->isOpen()) fst_->close();
    m_->final();
  }
  RtlSim(const RtlSim&) = delete;
  RtlSim& operator=(const RtlSim&) = delete;

  void set_reset(bool active) { m_->set_reset(active); }
  void present(const Txn* item) { ports_.drive(p(), item); }
  void configure(const Txn& item) { ports_.configure(p(), item); }
  void set_out_ready(bool ready) { ports_.set_out_ready(p(), ready); }
  void env_drive() { ports_.env_drive(p()); }
  void settle() { m_->eval(); }
  bool accepts(const Txn& item) const { return ports_.accepts(p(), item); }
  bool out_valid() const { return ports_.out_valid(p()); }
  Txn out() const { return ports_.out(p()); }
  void env_sample() { ports_.env_sample(p()); }
  bool quiet() const { return ports_.quiet(); }
  void clock() {
    dump(wave_cycle_ * kTimePerCycle);
    ctx_->time(wave_cycle_ * kTimePerCycle + kTimePerCycle / 2);  // assertion messages show it
    m_->rising_edge();
    if (ctx_->gotError()) {
      throw std::runtime_error("RTL assertion failed at cycle " +
                               std::to_string(static_cast<int64_t>(wave_cycle_) - kResetCycles) +
                               " (Verilator's %Error line above names it)");
    }
    dump(wave_cycle_ * kTimePerCycle + kTimePerCycle / 2);
    m_->clock_low();
    ++wave_cycle_;
  }
  void finish(RunResult& result) { ports_.finish(p(), result); }

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
  RtlPorts& p() const { return m_->ports(); }

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

  PortLogic<RtlPorts>& ports_;
  const TraceOptions* trace_;
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<RtlModel> m_;
  std::unique_ptr<VerilatedFstC> fst_;
  uint64_t wave_cycle_ = 0;  // counts reset cycles too
#if defined(VM_COVERAGE) && VM_COVERAGE
  std::string path_;
#endif
};

}  // namespace

RunResult run_rtl(PortLogic<RtlPorts>& ports, RtlModelFactory model, const std::vector<Txn>& items,
                  ItemPlan plan, const RunOptions& options) {
  RtlSim sim(ports, model, options);
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

}  // namespace tmu::tb
