// Compares one engine's run against the reference run, output by output, bit for bit, and
// the statistics counters the reference predicts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/engine.hpp"
#include "harness/txn.hpp"

namespace tmu::tb {

struct Mismatch {
  size_t output_index = 0;  // which output transaction
  std::vector<int> fields;  // fields that differ (empty when the output is missing)
  std::optional<Txn> expected;
  std::optional<Txn> got;  // empty when the engine produced too few outputs
};

struct Comparison {
  size_t compared = 0;    // outputs compared
  size_t mismatches = 0;  // outputs that differ, including missing and extra ones
  std::optional<Mismatch> first;
  // The memory requests, per request channel: the first that differs (or is missing or extra),
  // and how many do.
  struct RequestMismatch {
    size_t channel = 0;
    size_t differing = 0;
    Mismatch first;
  };
  std::vector<RequestMismatch> requests;
  std::vector<std::string> counter_diffs;  // "hits: expected 10, got 11"
  std::string error;                       // the engine's own failure (deadlock, duplicate)
  bool match() const {
    return mismatches == 0 && requests.empty() && counter_diffs.empty() && error.empty();
  }
};

// Outputs and every memory request (channel by channel, in order; `requests` the schemas of
// the request channels) bit for bit, and the counters where the reference reports them.
Comparison compare(const Schema& outputs, const RunResult& reference, const RunResult& got,
                   const std::vector<const Schema*>& requests = {});

// The per-field table of a mismatch: name, expected, got, and a marker on differing fields.
std::string mismatch_table(const Schema& outputs, const Mismatch& m);

}  // namespace tmu::tb
