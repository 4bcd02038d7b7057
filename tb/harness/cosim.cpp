#include "harness/cosim.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <filesystem>
#include <ostream>

#include "harness/rtl_runner.hpp"
#include "harness/scoreboard.hpp"
#include "harness/vector_file.hpp"
#include "harness/waveform.hpp"

namespace tmu::tb {
namespace {

// The stall generator is seeded from the stimulus seed so one --seed reproduces everything.
constexpr uint64_t kStallSeedSalt = 0x5A17'0000'0000'0001ull;
constexpr uint64_t kXSeeds[2] = {11, 22};

std::string repro_command(const Block& block, const CosimOptions& o) {
  std::string cmd =
      fmt::format("texsim cosim {} --seed {} --count {}", block.name(), o.seed, o.count);
  if (!o.vectors_in.empty()) cmd += " --vectors " + o.vectors_in;
  if (!o.directed) cmd += " --no-directed";
  cmd += fmt::format(" --in-idle {} --out-stall {}", o.in_idle, o.out_stall);
  if (o.inject_fault >= 0) cmd += fmt::format(" --inject-fault {}", o.inject_fault);
  const std::string extra = block.repro_options();
  if (!extra.empty()) cmd += " " + extra;
  return cmd;
}

std::string rate(size_t n, double seconds) {
  if (seconds <= 0.0) return "-";
  const double r = static_cast<double>(n) / seconds;
  return r >= 1e6 ? fmt::format("{:.2f} M/s", r / 1e6) : fmt::format("{:.1f} k/s", r / 1e3);
}

}  // namespace

std::vector<Txn> build_stimulus(const Block& block, const CosimOptions& options) {
  if (!options.vectors_in.empty()) return read_vectors(options.vectors_in, block.inputs());
  std::vector<Txn> items = block.setup_items();
  if (options.directed) {
    for (const Txn& t : block.directed_items()) items.push_back(t);
  }
  std::mt19937_64 rng(options.seed);
  for (const Txn& t : block.random_items(rng, options.count)) items.push_back(t);
  // Every field as its port carries it: generators may produce wider (e.g. negative) values.
  for (Txn& t : items) t = block.inputs().masked(t);
  return items;
}

CosimResult run_cosim(const Block& block, const CosimOptions& o, std::ostream& log,
                      const EngineFactory& override_engine) {
  CosimResult res;
  res.repro = repro_command(block, o);
  const std::vector<Txn> items = build_stimulus(block, o);
  res.items = items.size();
  if (!o.vectors_out.empty()) write_vectors(o.vectors_out, block.inputs(), items);

  auto make = [&](const std::string& level) {
    std::unique_ptr<Engine> e = override_engine ? override_engine(level) : nullptr;
    return e ? std::move(e) : block.engine(level);
  };

  RunOptions run_opt;
  run_opt.stalls = {o.seed ^ kStallSeedSalt, o.in_idle, o.out_stall};
  run_opt.x_seed = kXSeeds[0];

  const RunResult golden = make("golden")->run(items, run_opt);
  res.runs["golden"] = golden;
  if (!golden.error.empty()) throw std::runtime_error("golden model failed: " + golden.error);
  // The input item behind each output: as golden reports it, or one output per producing item.
  std::vector<size_t> item_of_output = golden.output_items;
  if (item_of_output.empty()) {
    for (size_t i = 0; i < items.size(); ++i) {
      if (block.produces_output(items[i])) item_of_output.push_back(i);
    }
  }
  fmt::print(log,
             "cosim {}: seed {}, {} items -> {} transactions; stalls: in-idle {}, out-stall {}\n",
             block.name(), o.seed, items.size(), golden.outputs.size(), o.in_idle, o.out_stall);
  fmt::print(log, "  {:<8} {:>10} outputs  {:>8.3f} s  {:>12}\n", "golden", golden.outputs.size(),
             golden.seconds, rate(golden.outputs.size(), golden.seconds));
  res.transactions = golden.outputs.size();

  res.pass = true;
  for (const std::string& level : o.engines) {
    const RunResult run = make(level)->run(items, run_opt);
    RunResult scored = run;  // what the scoreboard sees; the x-check uses the untouched run
    if (o.inject_fault >= 0 && static_cast<size_t>(o.inject_fault) < scored.outputs.size()) {
      scored.outputs[static_cast<size_t>(o.inject_fault)].f[0] ^= 1;  // a deliberate wrong bit
    }
    const Comparison c = compare(block.outputs(), golden, scored, block.request_schemas());
    // Cycles per transaction: the throughput (a pipelined block under no back-pressure nears 1).
    const double per_txn = static_cast<double>(run.cycles) /
                           static_cast<double>(std::max<size_t>(1, run.outputs.size()));
    fmt::print(log, "  {:<8} {:>10} outputs  {:>8.3f} s  {:>12}  {:>10} cycles {:>6.2f}/txn  {}\n",
               level, run.outputs.size(), run.seconds, rate(run.outputs.size(), run.seconds),
               run.cycles, per_txn, c.match() ? "MATCH" : "MISMATCH");
    res.runs[level] = run;
    if (c.match()) continue;

    res.pass = false;
    if (res.failing_engine.empty()) res.failing_engine = level;
    fmt::print(log, "\nMISMATCH {} vs golden: {} of {} outputs differ\n", level, c.mismatches,
               std::max(golden.outputs.size(), run.outputs.size()));
    if (!c.error.empty()) fmt::print(log, "  {} run failed: {}\n", level, c.error);
    for (const std::string& d : c.counter_diffs) fmt::print(log, "  counter {}\n", d);
    for (const Comparison::RequestMismatch& r : c.requests) {
      const Schema& schema = *block.request_schemas()[r.channel];
      fmt::print(log, "  memory requests of channel {}: {} differ; first at request {}\n{}",
                 r.channel, r.differing, r.first.output_index, mismatch_table(schema, r.first));
    }
    uint64_t fail_cycle = run.cycles;
    if (c.first) {
      const Mismatch& m = *c.first;
      const size_t item =
          m.output_index < item_of_output.size() ? item_of_output[m.output_index] : 0;
      if (m.got && m.output_index < run.output_cycles.size())
        fail_cycle = run.output_cycles[m.output_index];
      fmt::print(log, "  first at transaction {} (input item {}{})\n", m.output_index, item,
                 level == "golden" ? "" : fmt::format(", {} cycle {}", level, fail_cycle));
      fmt::print(log, "  inputs: {}\n", block.inputs().describe(items[item]));
      fmt::print(log, "{}", mismatch_table(block.outputs(), m));
    }
    fmt::print(log, "  reproduce: {} --engines {}\n", res.repro, level);

    if (level == "rtl") {  // a waveform window around the first failure
      try {
        const WaveWindow w =
            dump_waveform(*make("rtl"), items, run_opt, fail_cycle, o.wave_before, o.wave_after,
                          o.wave_dir, block.name() + "_mismatch", block.ports());
        res.wave_path = w.fst;
        fmt::print(log, "  waveform: {} (cycles {}..{}); view: gtkwave {}\n", w.fst, w.begin, w.end,
                   w.gtkw);
      } catch (const std::exception& e) {  // a model without tracing (a mutant)
        fmt::print(log, "  waveform: none ({})\n", e.what());
      }
    }
  }

  // X check: random initial values must not reach the outputs or the timing.
  if (o.x_check && res.runs.count("rtl")) {
    RunOptions second = run_opt;
    second.x_seed = kXSeeds[1];
    const RunResult again = make("rtl")->run(items, second);
    const RunResult& first = res.runs["rtl"];
    const bool same = again.outputs == first.outputs &&
                      again.output_cycles == first.output_cycles &&
                      again.counters == first.counters && again.requests == first.requests &&
                      again.error == first.error;
    fmt::print(log, "  x-check  rtl with random initial values, seeds {} and {}: {}\n", kXSeeds[0],
               kXSeeds[1], same ? "identical" : "DIFFERENT (an uninitialised value leaks)");
    res.x_check = same ? XCheck::kIdentical : XCheck::kDifferent;
    if (!same) {
      res.pass = false;
      if (res.failing_engine.empty()) res.failing_engine = "rtl x-check";
    }
  }

  // Coverage of the named cases over the stimulus, plus the reference's counters.
  for (const std::string& name : block.coverage_cases()) res.coverage[name] = 0;
  for (size_t k = 0; k < golden.outputs.size() && k < item_of_output.size(); ++k) {
    if (k > 0 && item_of_output[k] == item_of_output[k - 1]) continue;  // once per item
    block.cover(items, item_of_output[k], golden.outputs[k], res.coverage);
  }
  fmt::print(log, "coverage:\n");
  for (const std::string& name : block.coverage_cases()) {
    const uint64_t n = res.coverage[name];
    fmt::print(log, "  {:<36} {:>10}{}\n", name, n, n == 0 ? "  NOT HIT" : "");
  }
  for (const auto& [name, value] : golden.counters)
    fmt::print(log, "  counter {:<28} {:>10}\n", name, value);

  if (res.pass) {
    std::string who = "golden";
    for (const std::string& e : o.engines) who += " = " + e;
    fmt::print(log, "MATCH: all {} transactions bit-exact, {}\n", res.transactions, who);
  } else {
    fmt::print(log, "FAIL: {} disagrees with golden; reproduce: {}\n", res.failing_engine,
               res.repro);
  }
  return res;
}

}  // namespace tmu::tb
