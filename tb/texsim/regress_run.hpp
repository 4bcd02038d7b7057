// Runs a regression's tests (regress_list.hpp) as texsim processes, up to `jobs` at a time, each
// with its outputs in a folder of its own under `out` and its stdout and stderr in a log.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "texsim/regress_list.hpp"

namespace tmu::texsim {

struct RegressResult {
  RegressTest test;
  std::vector<std::string> command;  // the whole texsim command line that ran (reproduces it)
  int exit_code = 0;                 // texsim's: 0 pass, 1 mismatch, 2 bad input; -1 killed
  bool timed_out = false;
  double seconds = 0;
  std::filesystem::path log;                     // its stdout and stderr
  std::vector<std::filesystem::path> waveforms;  // the FST files it wrote (a mismatch's window)
  bool passed() const { return exit_code == 0; }
};

struct RegressOptions {
  std::string texsim;         // the binary the tests run
  std::filesystem::path out;  // logs/, waves/, renders/ under it
  int jobs = 1;
  double timeout_s = 600;  // a test still running then is killed and fails
};

// One test's outcome as a file (a Slurm array task writes it, the merge reads it):
// OUT/results/NAME.txt with "exit_code N", "seconds S", "timed_out 0|1".
void write_result_file(const RegressOptions& options, const RegressResult& result);
// The result of `test` from its file, with its command, log and waveforms as run_regression
// gives them; a test without a file (its task never ran) fails with exit code -1.
RegressResult read_result_file(const RegressOptions& options, const RegressTest& test);

// Runs every test; the results in the list's order. `progress` is called as each test ends.
std::vector<RegressResult> run_regression(const std::vector<RegressTest>& tests,
                                          const RegressOptions& options,
                                          void (*progress)(const RegressResult&) = nullptr);

}  // namespace tmu::texsim
