// A progress bar with rate and time left, on standard error, for runs longer than a second.
// Silent when standard error is not a terminal (CI logs, redirections).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace tmu::render {

class ProgressBar {
 public:
  ProgressBar(std::string label, std::string unit, bool enabled = true);
  ~ProgressBar();
  void update(uint64_t done, uint64_t total);  // cheap: draws at most ten times a second
  void finish();                               // clears the line

 private:
  std::string label_, unit_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace tmu::render
