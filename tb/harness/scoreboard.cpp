#include "harness/scoreboard.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace tmu::tb {

namespace {

// Transaction by transaction: how many compared, how many differ, the first that does.
struct SequenceDiff {
  size_t compared = 0, differing = 0;
  std::optional<Mismatch> first;
};

SequenceDiff diff(const Schema& schema, const std::vector<Txn>& expected,
                  const std::vector<Txn>& got) {
  SequenceDiff d;
  const size_t n = std::max(expected.size(), got.size());
  for (size_t i = 0; i < n; ++i) {
    Mismatch m;
    m.output_index = i;
    if (i < expected.size()) m.expected = expected[i];
    if (i < got.size()) m.got = got[i];
    if (m.expected && m.got) {
      ++d.compared;
      for (size_t f = 0; f < schema.size(); ++f) {
        const auto slot = static_cast<size_t>(schema.field(f).slot);
        if (m.expected->f[slot] != m.got->f[slot]) m.fields.push_back(static_cast<int>(f));
      }
      if (m.fields.empty()) continue;
    }
    ++d.differing;
    if (!d.first) d.first = m;
  }
  return d;
}

}  // namespace

Comparison compare(const Schema& outputs, const RunResult& reference, const RunResult& got,
                   const std::vector<const Schema*>& requests) {
  Comparison c;
  c.error = got.error;
  SequenceDiff d = diff(outputs, reference.outputs, got.outputs);
  c.compared = d.compared;
  c.mismatches = d.differing;
  c.first = std::move(d.first);
  static const std::vector<Txn> kNone;
  for (size_t r = 0; r < requests.size(); ++r) {
    const auto& want = r < reference.requests.size() ? reference.requests[r] : kNone;
    const auto& have = r < got.requests.size() ? got.requests[r] : kNone;
    SequenceDiff rd = diff(*requests[r], want, have);
    if (rd.differing > 0) c.requests.push_back({r, rd.differing, *rd.first});
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
    const auto slot = static_cast<size_t>(outputs.field(f).slot);
    const std::string e = m.expected ? outputs.value_text(fi, m.expected->f[slot]) : "(none)";
    const std::string g = m.got ? outputs.value_text(fi, m.got->f[slot]) : "(missing)";
    const bool differs =
        std::find(m.fields.begin(), m.fields.end(), fi) != m.fields.end() || !m.expected || !m.got;
    out += fmt::format("    {:<12} {:<24} {:<24}{}\n", outputs.fields()[f].name, e, g,
                       differs ? "  <-- differs" : "");
  }
  return out;
}

}  // namespace tmu::tb
