// `render --check`, unit by unit: every unit the render built against the same unit of the
// reference pipeline, with the co-simulation scoreboard (harness/scoreboard.hpp): every output
// transaction bit for bit, every memory request, every counter the reference reports. An error
// a later unit masks, or a wrong hit or miss count, fails the check although the pixels agree.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/scoreboard.hpp"
#include "render/units.hpp"

namespace tmu::render {

struct UnitCheck {
  size_t compared = 0;                   // units compared
  std::vector<std::string> differences;  // one line per differing unit, in the order they ran
  // The first differing unit (index into the render's units) and the cycle to centre its
  // waveform on: its first differing output's, or its run's end for a request or counter.
  std::optional<size_t> first_unit;
  uint64_t first_cycle = 0;
  bool match() const { return differences.empty(); }
};

// `got` against `reference` (the same scene and band at another level). Two pipelines that
// built different units differ at the first unit whose name differs.
UnitCheck check_units(const std::vector<UnitRun>& got, const std::vector<UnitRun>& reference);

}  // namespace tmu::render
