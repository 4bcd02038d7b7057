// Runs a Verilated block under the HandshakeDriver: reset, clocking, random initial values
// (--x-initial unique with a seed), and an optional FST window for debugging.
//
// A block plugs in with an RtlAdapter that maps transactions onto its ports. The runner
// requires only clk_i and rst_ni (active-low, synchronous) on the model.
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

#include "harness/engine.hpp"
#include "harness/handshake_driver.hpp"

namespace tmu::tb {

template <class Model>
class RtlAdapter {
 public:
  virtual ~RtlAdapter() = default;
  // Present `item` on its input channel (valid high), or nothing (every valid low).
  virtual void drive(Model& m, const Txn* item) = 0;
  // The channel of the presented item is ready (read after eval, before the edge).
  virtual bool accepts(const Model& m, const Txn& item) const = 0;
  virtual void set_out_ready(Model& m, bool ready) = 0;
  virtual bool out_valid(const Model& m) const = 0;
  virtual Txn out(const Model& m) const = 0;
  // The block's environment, e.g. a memory model: drive its inputs before eval, sample its
  // requests before the edge.
  virtual void env_drive(Model&) {}
  virtual void env_sample(const Model&) {}
  // A protocol or address error the environment saw; non-empty fails the run.
  virtual std::string env_error() const { return {}; }
  virtual Counters counters(const Model&) const { return {}; }
};

inline constexpr int kResetCycles = 5;
inline constexpr uint64_t kTimePerCycle = 10;  // waveform time units (ns) per clock

// Verilator rejects seed 0; map any 64-bit seed onto 1..2^31-1.
// Adds `error` to the run's error message (runs can fail in more than one way).
inline void append_error(RunResult& result, const std::string& error) {
  if (!error.empty()) result.error += (result.error.empty() ? "" : "; ") + error;
}

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

template <class Model>
RunResult run_rtl(RtlAdapter<Model>& adapter, const std::vector<Txn>& items,
                  size_t expected_outputs, const RunOptions& options) {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->randReset(2);  // every flop and memory starts random: reset bugs show up as X leaks
  ctx->randSeed(verilator_seed(options.x_seed));
  ctx->fatalOnError(false);  // a failed assertion fails this run, not the whole process
  const TraceOptions* trace = options.trace ? &*options.trace : nullptr;
  if (trace) ctx->traceEverOn(true);
  auto m = std::make_unique<Model>(ctx.get(), "TOP");
  std::unique_ptr<VerilatedFstC> fst;
  if (trace) {
    fst = std::make_unique<VerilatedFstC>();
    m->trace(fst.get(), 99);
  }

  HandshakeDriver driver(items, expected_outputs, options);
  uint64_t wave_cycle = 0;  // counts reset cycles too
  auto dump = [&](uint64_t time) {
    if (!fst) return;
    // The window in the driver's cycles, which are negative during reset; compared unsigned,
    // so that end_cycle's default (UINT64_MAX, the whole run) means what it says.
    const int64_t c = static_cast<int64_t>(wave_cycle) - kResetCycles;
    const bool in_window =
        (c < 0 || static_cast<uint64_t>(c) <= trace->end_cycle) && wave_cycle >= trace->begin_cycle;
    if (in_window && !fst->isOpen()) fst->open(trace->fst_path.c_str());
    if (in_window) fst->dump(time);
    if (!in_window && fst->isOpen()) fst->close();
  };
  auto tick = [&] {
    dump(wave_cycle * kTimePerCycle);
    ctx->time(wave_cycle * kTimePerCycle + kTimePerCycle / 2);  // assertion messages show it
    m->clk_i = 1;
    m->eval();
    if (ctx->gotError()) {
      throw std::runtime_error("RTL assertion failed at cycle " +
                               std::to_string(static_cast<int64_t>(wave_cycle) - kResetCycles) +
                               " (Verilator's %Error line above names it)");
    }
    dump(wave_cycle * kTimePerCycle + kTimePerCycle / 2);
    m->clk_i = 0;
    ++wave_cycle;
  };

  m->clk_i = 0;
  m->rst_ni = 0;
  for (int i = 0; i < kResetCycles; ++i) {
    adapter.drive(*m, nullptr);
    adapter.set_out_ready(*m, false);
    adapter.env_drive(*m);
    m->eval();
    tick();
  }
  m->rst_ni = 1;
#if defined(VM_COVERAGE) && VM_COVERAGE
  // Coverage build: the initialisation and reset go to a file of their own (<file>_reset.dat),
  // then the counters restart. scripts/coverage.sh counts their lines (constant tables, logic
  // fed by the static configuration only settle there), not their toggles (every flop changes
  // from its random initial value into reset).
  // Per instance: scripts/coverage.sh judges a bit's toggles in each instance on its own.
  const std::string coverage_path = coverage_file();
  if (!coverage_path.empty()) {
    ctx->coveragep()->forcePerInstance(true);
    ctx->coveragep()->write((coverage_path + "_reset.dat").c_str());
    ctx->coveragep()->zero();
  }
#endif

  const auto start = std::chrono::steady_clock::now();
  auto cycle = [&] {
    const Txn* item = driver.begin_cycle();
    adapter.drive(*m, item);
    adapter.set_out_ready(*m, driver.out_ready());
    adapter.env_drive(*m);
    m->eval();
    const bool in_fire = item != nullptr && adapter.accepts(*m, *item);
    const bool out_fire = driver.out_ready() && adapter.out_valid(*m);
    const Txn out = out_fire ? adapter.out(*m) : Txn{};
    adapter.env_sample(*m);
    tick();
    driver.end_cycle(in_fire, out_fire ? &out : nullptr);
  };
  RunResult& result = driver.result();
  try {
    while (!driver.done()) cycle();
    for (int i = 0; i < kDrainCycles; ++i) cycle();
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cycles = driver.cycle();
  result.counters = adapter.counters(*m);
  append_error(result, adapter.env_error());
  if (fst && fst->isOpen()) fst->close();
  m->final();
#if defined(VM_COVERAGE) && VM_COVERAGE
  // The counters live in this run's context: each run writes its own file (texsim runs several
  // models in one process); scripts/coverage.sh merges them.
  if (!coverage_path.empty()) ctx->coveragep()->write((coverage_path + ".dat").c_str());
#endif
  return std::move(result);
}

}  // namespace tmu::tb
