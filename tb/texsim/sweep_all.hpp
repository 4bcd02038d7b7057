// `texsim sweep all`: the project's accuracy document in one run. Every block's sweep (its
// width or configuration settings: error against the ideal model, Yosys cells and depth,
// cycles per pixel, simulation speed, the hardware against golden where a model of the setting
// exists), the model-level table (texsim levels), the default scene at every engine, and a plot
// per block of error against cells and against time (scripts/plot_accuracy.py), written as
// DIR/accuracy.md with its tables, CSV files and plots in DIR/accuracy/. The document opens with
// the legend of the marks every figure carries (sweep_support.hpp: Mark).
#pragma once

#include <cstddef>
#include <string>

namespace tmu::texsim {

struct SweepAllArgs {
  std::string out_dir = "docs";
  bool synth = true;           // the Yosys runs take most of the time
  size_t level_count = 20000;  // items per block in the model-level table
  std::string scene;           // empty: scenes/default.json of the source tree
  std::string python = "/usr/bin/python3";
};

void sweep_all(const SweepAllArgs& args);

}  // namespace tmu::texsim
