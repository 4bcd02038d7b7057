// The co-simulation flow every block shares: build the stimulus, run golden as the
// reference, run each engine under random back-pressure, score every output bit for bit,
// repeat the rtl run with a second random-initialisation seed (X check), count coverage,
// and on the first mismatch print the inputs, the per-field difference, the command that
// reproduces it and an FST waveform window with a GTKWave save file.
#pragma once

#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "harness/block.hpp"
#include "harness/engine.hpp"

namespace tmu::tb {

struct CosimOptions {
  uint64_t seed = 1;
  size_t count = 10000;  // random items after the setup and directed ones
  bool directed = true;
  std::string vectors_in;   // replay these items instead of directed + random
  std::string vectors_out;  // save the stimulus that was run
  std::vector<std::string> engines{"hls", "rtl"};  // each compared against golden
  double in_idle = 0.25;                           // probability of a bubble before each input item
  double out_stall = 0.25;                         // probability of output ready low in a cycle
  bool x_check = true;                             // rtl twice, different random initial values
  std::string wave_dir = "cosim_out";
  uint64_t wave_before = 64, wave_after = 16;  // cycles around the mismatch
  int64_t inject_fault = -1;  // flip bit 0 of this output of every engine (teeth check)
};

// What the X check saw: the rtl run again with other random initial values.
enum class XCheck { kNotRun, kIdentical, kDifferent };

struct CosimResult {
  bool pass = false;
  XCheck x_check = XCheck::kNotRun;
  size_t items = 0;
  size_t transactions = 0;  // outputs compared per engine
  std::map<std::string, RunResult> runs;
  std::string failing_engine;
  std::string wave_path;  // FST of the mismatch window, when one was written
  std::string repro;      // the command that reproduces the run
  Coverage coverage;
};

// Replaces Block::engine() for chosen levels (tests use it to run a mutated RTL).
using EngineFactory = std::function<std::unique_ptr<Engine>(const std::string& level)>;

CosimResult run_cosim(const Block& block, const CosimOptions& options, std::ostream& log,
                      const EngineFactory& override_engine = nullptr);

// The stimulus run_cosim builds: setup, directed, then `count` random items.
std::vector<Txn> build_stimulus(const Block& block, const CosimOptions& options);

}  // namespace tmu::tb
