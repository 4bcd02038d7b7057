// A Google Benchmark reporter that also prints, after the usual table, each benchmark's
// items per second and its ratio against a named peer measured in the same run.
#pragma once

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tmu::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  // pairs: (benchmark name, peer name) — the ratio printed is benchmark rate / peer rate.
  explicit RatioReporter(std::vector<std::pair<std::string, std::string>> pairs)
      : ConsoleReporter(::isatty(1) ? OO_Defaults : OO_Tabular), pairs_(std::move(pairs)) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      auto it = r.counters.find("items_per_second");
      if (it != r.counters.end()) rate_[r.benchmark_name()] = it->second.value;
    }
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    fmt::print("\n{:<46} {:>12} {:>40} {:>8}\n", "benchmark", "items/s", "peer", "ratio");
    for (const auto& [name, peer] : pairs_) {
      if (!rate_.count(name) || !rate_.count(peer)) continue;
      fmt::print("{:<46} {:>12.4g} {:>40} {:>8.4f}\n", name, rate_[name], peer,
                 rate_[name] / rate_[peer]);
    }
  }

 private:
  std::vector<std::pair<std::string, std::string>> pairs_;
  std::map<std::string, double> rate_;
};

}  // namespace tmu::bench
