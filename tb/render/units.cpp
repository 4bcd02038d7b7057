#include "render/units.hpp"

#include <map>
#include <mutex>
#include <stdexcept>

namespace tmu::render {

std::string_view name(Level level) {
  switch (level) {
    case Level::kIdeal:
      return "ideal";
    case Level::kGolden:
      return "golden";
    case Level::kHls:
      return "hls";
    case Level::kRtl:
      return "rtl";
  }
  return "?";
}

std::optional<Level> parse_level(std::string_view text) {
  for (Level l : {Level::kIdeal, Level::kGolden, Level::kHls, Level::kRtl}) {
    if (name(l) == text) return l;
  }
  return std::nullopt;
}

std::string engine_name(Level level) {
  return level == Level::kIdeal ? "golden" : std::string(name(level));
}

namespace {
// Units run on several threads at once (Pipeline::set_jobs).
std::mutex census_mutex;
std::map<std::string, UnitCensus>& census_map() {
  static std::map<std::string, UnitCensus> m;
  return m;
}
}  // namespace

UnitCensus census(const std::string& key) {
  const std::lock_guard<std::mutex> lock(census_mutex);
  return census_map()[key];
}
void count_built(const std::string& key) {
  const std::lock_guard<std::mutex> lock(census_mutex);
  ++census_map()[key].built;
}
void count_cycles(const std::string& key, uint64_t cycles) {
  const std::lock_guard<std::mutex> lock(census_mutex);
  census_map()[key].cycles += cycles;
}
void reset_census() {
  const std::lock_guard<std::mutex> lock(census_mutex);
  census_map().clear();
}

void run_unit(UnitRun& unit, Level level, const tb::RunOptions& options) {
  unit.result = unit.engine(engine_name(level))->run(unit.items, options);
  if (!unit.result.error.empty()) {
    throw std::runtime_error(unit.name() + " (" + engine_name(level) +
                             ") failed: " + unit.result.error);
  }
  for (const std::string& key : unit.census_keys()) count_cycles(key, unit.result.cycles);
}

uint64_t unit_cycles(const UnitRun& unit, bool* predicted) {
  if (predicted) *predicted = false;
  if (unit.result.cycles != 0) return unit.result.cycles;
  const auto accesses = tb::counter_value(unit.result.counters, "accesses");
  if (!accesses) return 0;
  if (predicted) *predicted = true;
  return *accesses + tb::counter_value(unit.result.counters, "slow_accesses").value_or(0);
}

std::vector<tb::Txn> run_and_keep(UnitRun unit, Level level,
                                  std::vector<size_t> fragments_of_outputs,
                                  std::vector<UnitRun>& units,
                                  std::vector<std::vector<size_t>>& outputs_of) {
  run_unit(unit, level, {});
  std::vector<tb::Txn> outputs = unit.result.outputs;
  units.push_back(std::move(unit));
  outputs_of.push_back(std::move(fragments_of_outputs));
  return outputs;
}

}  // namespace tmu::render
