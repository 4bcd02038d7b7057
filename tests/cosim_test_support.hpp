// Helpers shared by the co-simulation tests.
#pragma once

#include <unistd.h>

#include <filesystem>
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

}  // namespace tmu::tb::testing
