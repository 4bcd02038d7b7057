// A regression's results as JUnit XML (what CI dashboards read) and as a summary a person reads:
// the counts, then for each failure its reproduce command, its waveform and its log.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "texsim/regress_run.hpp"

namespace tmu::texsim {

// The command line of a result as a shell would take it.
std::string command_line(const std::vector<std::string>& command);

void write_junit(const std::filesystem::path& path, const std::string& suite,
                 const std::vector<RegressResult>& results);

// The summary's text.
std::string summary(const std::string& list, const std::vector<RegressResult>& results,
                    double seconds, int jobs);

}  // namespace tmu::texsim
