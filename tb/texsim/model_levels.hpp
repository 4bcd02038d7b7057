// What fidelity costs in simulation time: one workload through every model level of a block
// (ideal, golden, hls, rtl, rtl with FST tracing, rtl on two threads, Icarus Verilog), and a
// whole scene rendered at each engine. `texsim levels` prints them; `texsim sweep all` puts
// them in the accuracy document.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "texsim/sweep_support.hpp"

namespace tmu::texsim {

// Every level `texsim levels` tries, in print order. A block that has no engine at a level
// (no ideal model, not verilated with threads, not accepted by Icarus) shows why instead.
inline const std::vector<std::string> kModelLevels{"ideal",   "golden",      "hls",   "rtl",
                                                   "rtl-fst", "rtl-threads", "icarus"};

struct LevelRun {
  std::string level;
  size_t transactions = 0;  // outputs
  double seconds = 0;       // the model alone, as the engine times it
  std::string verdict;      // against golden: "yes", "NO: ...", or "-" (ideal, golden)
  std::string note;         // why a level did not run, or what it wrote
};

struct BlockLevels {
  std::string block, workload;
  std::vector<LevelRun> runs;
};

// The blocks `texsim levels` measures by default: those with every level built.
inline const std::vector<std::string> kLevelBlocks{"noise", "fractal", "trilinear"};

// Runs `count` random items (seeded) of `block` through every level, without stalls.
// inject_fault >= 0 flips bit 0 of that output of every level but golden before the
// comparison (proves that a wrong level is caught).
BlockLevels measure_levels(const std::string& block, size_t count, uint64_t seed, std::ostream& log,
                           int64_t inject_fault = -1);

// One row per (block, level): transactions per second and the ratio to golden.
SweepTable levels_table(const std::vector<BlockLevels>& results);

struct SceneLevel {
  std::string engine;
  double seconds = 0;  // the whole render: front end, textures, units
  double units_seconds = 0;
  std::string frame_verdict;  // hls, rtl: "yes" when its frame is golden's pixel for pixel; "-"
};

// Renders `scene` at ideal, golden, hls and rtl into `out_dir`; the wall time of each, and
// whether the hls and rtl frames equal golden's.
std::vector<SceneLevel> measure_scene_levels(const std::string& scene, const std::string& out_dir,
                                             std::ostream& log);
SweepTable scene_levels_table(const std::vector<SceneLevel>& results);

}  // namespace tmu::texsim
