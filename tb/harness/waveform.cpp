#include "harness/waveform.hpp"

#include <filesystem>

#include "harness/gtkw.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

WaveWindow dump_waveform(Engine& engine, const std::vector<Txn>& items, RunOptions options,
                         uint64_t fail_cycle, uint64_t before, uint64_t after,
                         const std::string& dir, const std::string& stem,
                         const std::vector<Port>& ports) {
  std::filesystem::create_directories(dir);
  WaveWindow w;
  w.fst = (std::filesystem::path(dir) / (stem + ".fst")).string();
  w.gtkw = (std::filesystem::path(dir) / (stem + ".gtkw")).string();
  w.begin = fail_cycle > before ? fail_cycle - before : 0;
  w.end = fail_cycle + after;
  options.trace = TraceOptions{w.fst, w.begin, w.end};
  engine.run(items, options);
  const uint64_t t0 = (w.begin + kResetCycles) * kTimePerCycle;
  write_gtkw(w.gtkw, w.fst, ports, w.begin > 0 ? t0 : 0, (w.end + kResetCycles) * kTimePerCycle,
             (fail_cycle + kResetCycles) * kTimePerCycle);
  return w;
}

}  // namespace tmu::tb
