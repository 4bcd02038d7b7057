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
  std::string kind;      // the block: trilinear, footprint, mipgen, deflect, ...
  std::string material;  // the material whose chain built it
  std::string role;      // what a map unit reads for it ("bump", "environment+X"), or empty
  // The unit's engine at a level ("golden", "hls", "rtl").
  std::function<std::unique_ptr<tb::Engine>(const std::string& level)> engine;
  // Its block: the schemas the unit-by-unit check reads, the ports a waveform shows.
  std::shared_ptr<const tb::Block> block;
  std::vector<tb::Txn> items;  // its stimulus
  tb::RunResult result;        // its outputs, cycles and counters

  std::string name() const {
    return kind + "[" + material + (role.empty() ? "" : "." + role) + "]";
  }
  // Where the census counts it: its kind, and kind.role for a unit with a role
  // ("trilinear", "trilinear.bump").
  std::vector<std::string> census_keys() const {
    if (role.empty()) return {kind};
    return {kind, kind + "." + role};
  }
};

// A stage of the documents' pipelines that a render at golden, hls or rtl computes on the host
// rather than in a unit, and why. The render report lists them.
struct HostWork {
  std::string stage, reason;
  friend bool operator==(const HostWork&, const HostWork&) = default;
};

// How many units of each kind this process has built (engines constructed, at any level, by
// the factory attach() gives them) and how many cycles they ran: the proof that a scene builds
// and clocks only the units it calls for. A unit with a role counts under its kind and under
// kind.role too ("trilinear" and "trilinear.diffuse"), so each map of a chain can be told apart.
struct UnitCensus {
  uint64_t built = 0;
  uint64_t cycles = 0;
};
UnitCensus census(const std::string& key);
void count_built(const std::string& key);
void count_cycles(const std::string& key, uint64_t cycles);
void reset_census();

// A unit's engines and block from a block that owns its environment.
// Set run.kind (and run.role) first: each engine the factory constructs counts in their census.
template <class Block>
void attach(UnitRun& run, std::shared_ptr<Block> block) {
  run.block = block;
  run.engine = [block, keys = run.census_keys()](const std::string& level) {
    for (const std::string& key : keys) count_built(key);
    return block->engine(level);
  };
}

// A unit's cycles: its own, or for an untimed golden unit the memory periods its counters
// predict (the trilinear unit is memory-bound: one period per access, two for a slow one);
// `predicted` says which. 0 for an untimed unit without those counters.
uint64_t unit_cycles(const UnitRun& unit, bool* predicted = nullptr);

// Runs a unit's engine at `level` (not ideal) over its items and records it in the census.
void run_unit(UnitRun& unit, Level level, const tb::RunOptions& options);

// A unit of a chain: runs it (run_unit), keeps it in `units` with the fragment index of each of
// its outputs in `outputs_of`, and returns its outputs for the next unit.
std::vector<tb::Txn> run_and_keep(UnitRun unit, Level level,
                                  std::vector<size_t> fragments_of_outputs,
                                  std::vector<UnitRun>& units,
                                  std::vector<std::vector<size_t>>& outputs_of);

}  // namespace tmu::render
