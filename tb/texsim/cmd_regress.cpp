// `texsim regress LIST`: a regression (cosim seeds and scene renders, regress_list.hpp) run on
// N parallel jobs on this machine; every test a texsim process with its own outputs; one JUnit
// XML and one summary with each failure's reproduce command, waveform and log
// (docs/regress.md). Exit 0 when every test passed, 1 when one failed, 2 for a bad list.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "texsim/commands.hpp"
#include "texsim/regress_list.hpp"
#include "texsim/regress_report.hpp"
#include "texsim/regress_run.hpp"

namespace tmu::texsim {
namespace {

namespace fs = std::filesystem;

struct Args {
  std::string list, out = "regress_out";
  int jobs = 0;
  double timeout = 600;
};

// This texsim, for the tests: the same build runs them.
std::string self() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("regress: cannot find texsim's own path");
  return p.string();
}

void report_line(const RegressResult& r) {
  fmt::print("  {} {} ({:.1f} s)\n", r.passed() ? "pass" : "FAIL", r.test.name, r.seconds);
  std::fflush(stdout);
}

int run(const Args& a) {
  const std::vector<RegressTest> tests = read_regress_list(a.list);
  RegressOptions o;
  o.texsim = self();
  o.out = fs::absolute(a.out);
  o.jobs =
      a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.timeout_s = a.timeout;
  fmt::print("regression {}: {} tests on {} jobs, outputs in {}\n", a.list, tests.size(), o.jobs,
             o.out.string());
  std::fflush(stdout);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<RegressResult> results = run_regression(tests, o, report_line);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_junit(o.out / "junit.xml", "texsim regress " + fs::path(a.list).filename().string(),
              results);
  const std::string text = summary(a.list, results, seconds, o.jobs);
  write_file_atomically((o.out / "summary.txt").string(), text);
  fmt::print("\n{}junit: {}\nsummary: {}\n", text, (o.out / "junit.xml").string(),
             (o.out / "summary.txt").string());
  for (const RegressResult& r : results) {
    if (!r.passed()) return 1;
  }
  return 0;
}

}  // namespace

void add_regress_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "regress",
      "Run a regression list on this machine: `cosim BLOCK [--seeds A..B] [options]` and `render "
      "SCENE [options]` lines, each test a texsim process, --jobs at a time; writes OUT/junit.xml, "
      "OUT/summary.txt (each failure's reproduce command, waveform and log) and OUT/logs/. Exit 0 "
      "all passed, 1 a test failed, 2 a bad list (docs/regress.md)");
  auto a = std::make_shared<Args>();
  cmd->add_option("list", a->list, "The regression list")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", a->out, "Where the logs, waveforms, renders and reports go")
      ->capture_default_str();
  cmd->add_option("--jobs,-j", a->jobs, "Tests at a time (default: the cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--timeout", a->timeout, "Seconds after which a test is killed and fails")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->callback([a, &exit_code] { exit_code.value = run(*a); });
}

}  // namespace tmu::texsim
