// Shared pieces of the accuracy sweeps: their options, a table printed as aligned text and as
// Markdown, and the Yosys figures of a block at given parameters (scripts/synth.sh).
#pragma once

#include <string>
#include <utility>
#include <vector>

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

class SweepTable {
 public:
  explicit SweepTable(std::vector<std::string> header) : header_(std::move(header)) {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  std::string last_row_text() const;
  // Prints the aligned table; when `markdown_path` is not empty, writes it there as Markdown
  // and beside it as CSV (same stem, .csv) for scripts/plot_accuracy.py.
  void print(const std::string& markdown_path) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
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

// How many synthesize() calls of this process ran Yosys and how many the cache answered.
struct SynthCounts {
  int run = 0, cached = 0;
};
SynthCounts synth_counts();

struct RtlSpeed {
  double samples_per_second = 0;  // 0: no Verilated model at this setting
  std::string verdict = "-";      // "yes" when bit-exact with golden on the test pattern
  std::string text() const;
};

// The trilinear unit's rtl at `widths` on the floor view of `texture`, when a Verilated model
// of that setting was built (rtl/CMakeLists.txt builds the sweep's settings).
RtlSpeed measure_trilinear_rtl(const texram::Widths& widths, const texram::TexramTexture& texture,
                               const texram::SamplerConfig& config, const SweepArgs& args);

}  // namespace tmu::texsim
