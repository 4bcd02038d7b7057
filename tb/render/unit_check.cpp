#include "render/unit_check.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace tmu::render {
namespace {

// One line: what differs first, and how much.
std::string describe(const UnitRun& unit, const tb::Comparison& c) {
  std::vector<std::string> parts;
  if (!c.error.empty()) parts.push_back("run failed: " + c.error);
  if (c.first) {
    const tb::Mismatch& m = *c.first;
    std::vector<std::string> fields;
    for (int f : m.fields)
      fields.push_back(unit.block->outputs().field(static_cast<size_t>(f)).name);
    parts.push_back(fmt::format("{} of {} outputs differ, first output {} ({})", c.mismatches,
                                c.compared, m.output_index,
                                m.got ? fmt::format("{}", fmt::join(fields, ", ")) : "missing"));
  }
  for (const tb::Comparison::RequestMismatch& r : c.requests) {
    parts.push_back(fmt::format("{} memory requests of channel {} differ, first request {}",
                                r.differing, r.channel, r.first.output_index));
  }
  for (const std::string& d : c.counter_diffs) parts.push_back("counter " + d);
  return fmt::format("{}: {}", unit.name(), fmt::join(parts, "; "));
}

}  // namespace

UnitCheck check_units(const std::vector<UnitRun>& got, const std::vector<UnitRun>& reference) {
  UnitCheck check;
  const size_t n = std::min(got.size(), reference.size());
  for (size_t u = 0; u < n; ++u) {
    if (got[u].name() != reference[u].name()) {
      check.differences.push_back(fmt::format("unit {}: this render built {}, the reference {}", u,
                                              got[u].name(), reference[u].name()));
      if (!check.first_unit) check.first_unit = u;
      return check;  // the chains went apart: the units after are not each other's
    }
    ++check.compared;
    const tb::Comparison c = tb::compare(got[u].block->outputs(), reference[u].result,
                                         got[u].result, got[u].block->request_schemas());
    if (c.match()) continue;
    check.differences.push_back(describe(got[u], c));
    if (check.first_unit) continue;
    check.first_unit = u;
    const auto& cycles = got[u].result.output_cycles;
    check.first_cycle = c.first && c.first->output_index < cycles.size()
                            ? cycles[c.first->output_index]
                            : got[u].result.cycles;
  }
  if (got.size() != reference.size()) {
    check.differences.push_back(
        fmt::format("this render built {} units, the reference {}", got.size(), reference.size()));
  }
  return check;
}

}  // namespace tmu::render
