#include "harness/scoreboard.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace tmu::tb {

Comparison compare(const Schema& outputs, const RunResult& reference, const RunResult& got) {
  Comparison c;
  c.error = got.error;
  const size_t n = std::max(reference.outputs.size(), got.outputs.size());
  for (size_t i = 0; i < n; ++i) {
    Mismatch m;
    m.output_index = i;
    if (i < reference.outputs.size()) m.expected = reference.outputs[i];
    if (i < got.outputs.size()) m.got = got.outputs[i];
    if (m.expected && m.got) {
      ++c.compared;
      for (size_t f = 0; f < outputs.size(); ++f) {
        if (m.expected->f[f] != m.got->f[f]) m.fields.push_back(static_cast<int>(f));
      }
      if (m.fields.empty()) continue;
    }
    ++c.mismatches;
    if (!c.first) c.first = m;
  }
  for (const auto& [name, value] : reference.counters) {
    auto it = std::find_if(got.counters.begin(), got.counters.end(),
                           [&](const auto& kv) { return kv.first == name; });
    if (it == got.counters.end()) {
      c.counter_diffs.push_back(fmt::format("{}: expected {}, not reported", name, value));
    } else if (it->second != value) {
      c.counter_diffs.push_back(fmt::format("{}: expected {}, got {}", name, value, it->second));
    }
  }
  return c;
}

std::string mismatch_table(const Schema& outputs, const Mismatch& m) {
  std::string out = fmt::format("    {:<12} {:<24} {:<24}\n", "field", "expected", "got");
  for (size_t f = 0; f < outputs.size(); ++f) {
    const int fi = static_cast<int>(f);
    const std::string e = m.expected ? outputs.value_text(fi, m.expected->f[f]) : "(none)";
    const std::string g = m.got ? outputs.value_text(fi, m.got->f[f]) : "(missing)";
    const bool differs =
        std::find(m.fields.begin(), m.fields.end(), fi) != m.fields.end() || !m.expected || !m.got;
    out += fmt::format("    {:<12} {:<24} {:<24}{}\n", outputs.fields()[f].name, e, g,
                       differs ? "  <-- differs" : "");
  }
  return out;
}

}  // namespace tmu::tb
