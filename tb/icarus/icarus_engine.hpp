// The same RTL under Icarus Verilog, a second simulator (docs/harness.md, "Icarus Verilog").
//
// An Icarus engine runs a block's RTL (its sources from rtl/manifest.txt) inside a small
// SystemVerilog testbench (tb/icarus/<testbench>.sv with the shared cycle loop
// tb/icarus/stream_tb.svh): the input items go to a vector file (one item per line, fields in
// hex), `vvp` simulates, and the output transactions come back from a file (one per line).
// RunResult::seconds is the wall time of the vvp process alone (load, simulate, file I/O),
// not the compilation.
//
// Compilation happens on first use and is cached: the sources are read, passed through the
// Icarus 11 compatibility rewrite below, hashed (with the testbench, defines, parameters and
// the iverilog path), and compiled once by `iverilog -g2012 -DSYNTHESIS` into
// <cache>/<testbench>-<hash>/model.vvp; a later run, in this process or another, finds it.
// The cache is $TMU_ICARUS_CACHE, else <build dir>/icarus.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/engine.hpp"
#include "harness/txn.hpp"

namespace tmu::tb {

// One piece of text of one source replaced: a deliberately broken copy (like tmu_mutant in
// rtl/CMakeLists.txt), for the tests that the comparison has teeth.
struct IcarusMutation {
  std::string file;  // relative to rtl/
  std::string from, to;
};

struct IcarusModel {
  IcarusModel(std::string testbench_, std::string top_)
      : testbench(std::move(testbench_)), top(std::move(top_)) {}

  std::string testbench;  // the testbench module's name
  std::string top;        // the DUT's module: its sources are its line of rtl/manifest.txt
  std::string text;       // the testbench, generated from the ports (tb/icarus/testbench.hpp)
  std::optional<IcarusMutation> mutation;
};

// Whether an item produces an output transaction; empty: every item does.
using ProducesOutput = std::function<bool(const Txn&)>;

// An engine named `name` that runs `model`; items carry the `inputs` fields in order (written
// in hex as the testbench reads them), outputs the `outputs` fields. A run reports an error
// (RunResult::error) when the compilation fails, the simulation ends early, an output has X
// or Z bits, or there are too few or too many outputs. Throws std::invalid_argument ("iverilog
// not found") when configure did not find Icarus. The testbench sees `TMU_DUT = model.top.
std::unique_ptr<Engine> make_icarus_engine(const std::string& name, IcarusModel model,
                                           const Schema& inputs, const Schema& outputs,
                                           ProducesOutput produces_output = nullptr);

// The sources of a top of rtl/manifest.txt, relative to rtl/, in the order to read them
// (tmu_pkg.sv first); throws std::runtime_error when the manifest does not have it.
std::vector<std::string> manifest_sources(const std::string& top);

// The compiled model (the .vvp file), compiling it if the cache lacks it; throws
// std::runtime_error with iverilog's messages when it cannot. compile_seconds (if given) gets
// the time spent compiling (0 when cached).
std::string icarus_compile(const IcarusModel& model, double* compile_seconds = nullptr);

// The Icarus 11 compatibility rewrite of one RTL source (file name relative to rtl/), three
// rules, each a text change to an equivalent SystemVerilog form that Icarus 11 parses:
//   1. `parameter|localparam int unsigned` -> `... bit [31:0]` (Icarus 11 does not parse a
//      signing after `int` in a parameter declaration; both are 32-bit two-state unsigned);
//   2. an elaboration-time `$error(...)` alone on a line (the parameter checks in generate
//      blocks, never elaborated for the shipped parameters) -> `initial $error(...)`
//      (Icarus 11 has no elaboration system tasks);
//   3. in tmu_pkg.sv only, a typedef's `[NameW-1:0]` -> `[<value of NameW>-1:0]` (Icarus 11
//      resolves a package typedef's range in the scope of the module that uses it and fails
//      or crashes).
// The assertions (`ifndef SYNTHESIS`, concurrent assertions Icarus 11 does not have) are left
// out by compiling with -DSYNTHESIS, as Yosys does.
std::string icarus_compat_source(const std::string& file, const std::string& text);

}  // namespace tmu::tb
