// Helpers shared by the co-simulation tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
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

}  // namespace tmu::tb::testing
