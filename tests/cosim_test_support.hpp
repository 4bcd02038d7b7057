// Helpers shared by the co-simulation tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "harness/cosim.hpp"

namespace tmu::tb::testing {

// A directory of this test process under the system's temporary directory.
inline std::filesystem::path temp_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

// Cosim options for a test: the seed, the random count and the engines to compare; mismatch
// waveforms go to the test's temporary directory.
inline CosimOptions cosim_options(uint64_t seed, size_t count, std::vector<std::string> engines) {
  CosimOptions o;
  o.seed = seed;
  o.count = count;
  o.engines = std::move(engines);
  o.wave_dir = (temp_dir("tmu_cosim_test") / "waves").string();
  return o;
}

// A deliberately broken rtl model was caught: the run failed on the rtl engine, the log names
// the command that reproduces it (`repro`, e.g. "texsim cosim ccc --seed 9") and a non-empty
// mismatch waveform was written. Prints the mismatch report's start, for the reader.
inline void expect_rtl_caught_with_waveform(const CosimResult& r, const std::string& log,
                                            const std::string& repro) {
  EXPECT_FALSE(r.pass);
  EXPECT_EQ(r.failing_engine, "rtl");
  EXPECT_NE(log.find("reproduce: " + repro), std::string::npos) << log;
  ASSERT_FALSE(r.wave_path.empty());
  EXPECT_GT(std::filesystem::file_size(r.wave_path), 0u);
  const size_t at = log.find("MISMATCH rtl");
  if (at != std::string::npos) std::cout << log.substr(at, 900) << "...\n";
}

// A throughput a block promises: `count` random items (seed 3; the directed ones before them
// unless `directed` is false) with no input bubbles and no output stalls pass golden = hls =
// rtl, and each level of `extra` takes at most the items' count plus its extra cycles (its
// latency and the harness's 16 drain cycles).
inline void expect_full_rate(const Block& block, size_t count,
                             const std::map<std::string, uint64_t>& extra, bool directed = true) {
  CosimOptions o = cosim_options(3, count, {"hls", "rtl"});
  o.directed = directed;
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  for (const auto& [level, cycles] : extra) {
    EXPECT_LE(r.runs.at(level).cycles, r.items + cycles) << level << "\n" << log.str();
  }
}

// `items` run on golden, hls and rtl (no stalls) give no run error and as many outputs as
// `want` has, output i's `field` being want[i] on each.
inline void expect_outputs(const Block& block, const std::vector<Txn>& items, int field,
                           const std::vector<uint64_t>& want) {
  for (const std::string level : {"golden", "hls", "rtl"}) {
    const RunResult r = block.engine(level)->run(items, RunOptions{});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs.size(), want.size()) << level;
    for (size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(r.outputs[i].f[field], want[i]) << level << ", output " << i;
    }
  }
}

}  // namespace tmu::tb::testing
