// Shared pieces of the accuracy sweeps: their options, a table printed as aligned text and as
// Markdown with every figure marked by how it was obtained, the Yosys figures of a block at
// given parameters (scripts/synth.sh), and the hardware at a setting simulated against golden.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "blocks/registry.hpp"
#include "harness/engine.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"

namespace tmu::texsim {

struct SweepArgs {
  std::string block;
  std::string settings = "8,8,8;7,7,7;6,6,6;5,5,5;4,4,4;8,4,8;4,8,8;8,8,3";
  int requests = 20000;
  std::string out_dir;
  std::string markdown;
  bool synth = true;
};

// How a figure was obtained. A reader of a table must tell a figure of hardware that was checked
// against golden from one of a design nobody simulated at that setting, a formula or a model's
// prediction: every column's header names its mark, and a cell obtained otherwise names its own.
enum class Mark {
  kNone,       // not a figure: a setting, a name, a verdict's words
  kSim,        // measured on a hardware model compared bit for bit with golden in this run
  kSynth,      // Yosys, of RTL that a simulation in this run showed equal to golden there
  kSynthOnly,  // Yosys, of RTL that no simulation in this run showed equal to golden there
  kFormula,    // computed from the setting or from counts, not measured
  kModel,      // from a C++ model (golden, ideal, the page model, OpenImageIO), not hardware
};

// "sim", "synth", "synth only", "formula", "model" ("" for kNone).
std::string mark_name(Mark mark);
// What each mark means, as a Markdown list (the head of docs/accuracy.md).
std::string marks_legend();

// A column's name or a cell's text, with its mark (a cell's kNone: its column's).
struct Marked {
  Marked(std::string text_, Mark mark_ = Mark::kNone) : text(std::move(text_)), mark(mark_) {}
  Marked(const char* text_, Mark mark_ = Mark::kNone) : text(text_), mark(mark_) {}
  std::string text;
  Mark mark;
};
using Column = Marked;
using Cell = Marked;

class SweepTable {
 public:
  explicit SweepTable(std::vector<Column> columns) : columns_(std::move(columns)) {}
  void add(std::vector<Cell> row) { rows_.push_back(std::move(row)); }
  std::string last_row_text() const;
  // Prints the aligned table; when `markdown_path` is not empty, writes it there as Markdown
  // and beside it as CSV (same stem, .csv) for scripts/plot_accuracy.py. The text and the
  // Markdown show the marks ("cells [synth]", "1234 [synth only]"); the CSV holds the bare
  // names and figures, which the plot script looks up and parses.
  void print(const std::string& markdown_path) const;

 private:
  std::vector<std::string> header_text() const;
  std::vector<std::string> row_text(const std::vector<Cell>& row) const;
  std::vector<std::vector<std::string>> rows_text() const;
  std::vector<Column> columns_;
  std::vector<std::vector<Cell>> rows_;
};

// `texsim sweep trilinear` (cmd_sweep.cpp).
void sweep_trilinear(const SweepArgs& args);

struct SynthFigures {
  std::string cells = "-", logic = "-", depth = "-";
};

// Runs scripts/synth.sh --figures on `top` with the parameters overridden; "?" figures when it
// fails. The script caches every result in the build directory (synth_cache/), keyed by the
// top, the parameters, the Yosys version, the script and the top's sources.
SynthFigures synthesize(const std::string& top,
                        const std::vector<std::pair<std::string, int>>& params);

// A Yosys figure of the RTL at a row's setting: marked synth only unless a simulation in this
// run showed that RTL equal to golden. A cell without a figure ("-" not run, "?" failed, "n/a")
// keeps its column's mark.
Cell synth_cell(const std::string& figure, bool simulated);

// How many synthesize() calls of this process ran Yosys and how many the cache answered.
struct SynthCounts {
  int run = 0, cached = 0;
};
SynthCounts synth_counts();

struct RtlSpeed {
  double samples_per_second = 0;     // 0: no Verilated model at this setting
  std::string verdict = "no model";  // "yes" when bit-exact with golden on the test pattern
  bool simulated() const { return verdict == "yes"; }
  std::string text() const;
};

// The trilinear unit's rtl at `widths` on the floor view of `texture`, when a Verilated model
// of that setting was built (rtl/CMakeLists.txt builds the sweep's settings).
RtlSpeed measure_trilinear_rtl(const texram::Widths& widths, const texram::TexramTexture& texture,
                               const texram::SamplerConfig& config, const SweepArgs& args);

// A block's hardware at a sweep's setting (`options`) against golden, as `texsim cosim BLOCK`
// compares them (outputs, counters, memory requests; directed and `count` random items, without
// back-pressure): the Verilated model where the build made one of that setting
// (rtl/blocks.cmake), else Icarus Verilog where the block runs its RTL at any setting (at most
// kIcarusItems random items: it is about a hundred times slower). A mismatch prints the
// co-simulation's report.
struct RtlCheck {
  std::string simulator;  // "rtl" (Verilator), "icarus", or "" when neither has the setting
  bool match = false;
  tb::RunResult run;  // the simulator's
  bool simulated() const { return !simulator.empty() && match; }
  std::string verdict() const;  // "yes", "yes (Icarus)", "NO", "no model"
};
inline constexpr size_t kIcarusItems = 2000;
RtlCheck check_rtl(const std::string& block, const tb::BlockOptions& options, size_t count);

}  // namespace tmu::texsim
