#include "render/units.hpp"

#include <map>
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
std::map<std::string, UnitCensus>& census_map() {
  static std::map<std::string, UnitCensus> m;
  return m;
}
}  // namespace

UnitCensus& census(const std::string& key) { return census_map()[key]; }
void reset_census() { census_map().clear(); }

void run_unit(UnitRun& unit, Level level, const tb::RunOptions& options) {
  unit.result = unit.engine(engine_name(level))->run(unit.items, options);
  if (!unit.result.error.empty()) {
    throw std::runtime_error(unit.name() + " (" + engine_name(level) +
                             ") failed: " + unit.result.error);
  }
  for (const std::string& key : unit.census_keys()) census(key).cycles += unit.result.cycles;
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
