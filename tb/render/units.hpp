// The texture pipeline a scene calls for (000 §14, map linking): each material compiles to a
// chain of units, and only the units some chain references are built and clocked. The units
// are the co-simulation blocks, run at one model level.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/block.hpp"
#include "harness/engine.hpp"

namespace tmu::render {

// The model level a render runs at.
enum class Level { kIdeal, kGolden, kHls, kRtl };
std::string_view name(Level level);
std::optional<Level> parse_level(std::string_view text);
// The co-simulation engine name of a level ("golden", "hls", "rtl"); ideal runs no engine.
std::string engine_name(Level level);

// One unit built for one material: what it did.
struct UnitRun {
  std::string kind;      // trilinear, lowcost, mipgen
  std::string material;  // the material whose chain built it
  // The unit's engine at a level ("golden", "hls", "rtl"), and its ports (for a waveform).
  std::function<std::unique_ptr<tb::Engine>(const std::string& level)> engine;
  std::vector<tb::Port> ports;
  std::vector<tb::Txn> items;  // its stimulus
  tb::RunResult result;        // its outputs, cycles and counters

  std::string name() const { return kind + "[" + material + "]"; }
};

// How many units of each kind this process has built (engines constructed, at any level, by
// the factory attach() gives them) and how many cycles they ran: the proof that a scene builds
// and clocks only the units it calls for.
struct UnitCensus {
  uint64_t built = 0;
  uint64_t cycles = 0;
};
UnitCensus& census(const std::string& kind);
void reset_census();

// A unit's engines and ports from a block that owns its environment.
// Set run.kind first: each engine the factory constructs counts in that kind's census.
template <class Block>
void attach(UnitRun& run, std::shared_ptr<Block> block) {
  run.ports = block->ports();
  run.engine = [block, kind = run.kind](const std::string& level) {
    ++census(kind).built;
    return block->engine(level);
  };
}

// Runs a unit's engine at `level` (not ideal) over its items and records it in the census.
void run_unit(UnitRun& unit, Level level, const tb::RunOptions& options);

// A unit of a chain: runs it (run_unit), keeps it in `units` with the fragment index of each of
// its outputs in `outputs_of`, and returns its outputs for the next unit.
std::vector<tb::Txn> run_and_keep(UnitRun unit, Level level,
                                  std::vector<size_t> fragments_of_outputs,
                                  std::vector<UnitRun>& units,
                                  std::vector<std::vector<size_t>>& outputs_of);

}  // namespace tmu::render
