// The FST waveform window around a failure, with a GTKWave save file: reruns an rtl engine on
// the same items with the same options (runs are deterministic) and traces only the window.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "harness/block.hpp"
#include "harness/engine.hpp"

namespace tmu::tb {

struct WaveWindow {
  std::string fst, gtkw;        // the files written
  uint64_t begin = 0, end = 0;  // cycles (after reset) in the window
};

// Traces cycles [fail_cycle - before, fail_cycle + after] of `engine` on `items` into
// dir/stem.fst and writes dir/stem.gtkw showing `ports` with a marker on fail_cycle.
WaveWindow dump_waveform(Engine& engine, const std::vector<Txn>& items, RunOptions options,
                         uint64_t fail_cycle, uint64_t before, uint64_t after,
                         const std::string& dir, const std::string& stem,
                         const std::vector<Port>& ports);

}  // namespace tmu::tb
