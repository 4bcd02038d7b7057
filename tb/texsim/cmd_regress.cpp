// `texsim regress LIST`: a regression (cosim seeds and scene renders, regress_list.hpp) run on
// N parallel jobs on this machine, or as a Slurm job array; every test a texsim process with its
// own outputs; one JUnit XML and one summary with each failure's reproduce command, waveform and
// log (docs/regress.md). Exit 0 when every test passed, 1 when one failed, 2 for a bad list.
#include <fmt/format.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "texsim/commands.hpp"
#include "texsim/regress_join.hpp"
#include "texsim/regress_list.hpp"
#include "texsim/regress_report.hpp"
#include "texsim/regress_run.hpp"

namespace tmu::texsim {
namespace {

namespace fs = std::filesystem;

struct RegressArgs {
  std::string list, out = "regress_out";
  int jobs = 0;
  double timeout = 600;
  bool slurm = false, no_wait = false, merge = false;
  std::optional<size_t> task;
  std::string sbatch = "sbatch", sbatch_args;
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

// The JUnit XML and the summary of `results`; the exit code.
int report(const RegressArgs& a, const RegressOptions& o, const std::vector<RegressResult>& results,
           double seconds) {
  write_junit(o.out / "junit.xml", "texsim regress " + fs::path(a.list).filename().string(),
              results);
  std::string text = summary(a.list, results, seconds, o.jobs);
  bool merged = true;
  for (const GroupJoin& j : join_groups(o, results)) {
    text += "\n" + j.summary() + "\n";
    merged = merged && j.joined();
  }
  write_file_atomically((o.out / "summary.txt").string(), text);
  fmt::print("\n{}junit: {}\nsummary: {}\n", text, (o.out / "junit.xml").string(),
             (o.out / "summary.txt").string());
  for (const RegressResult& r : results) {
    if (!r.passed()) return 1;
  }
  return merged ? 0 : 1;
}

// The Slurm job array: one task per test, each `texsim regress LIST --task I` with the same
// outputs, --jobs of them at a time (docs/regress.md shows the script).
fs::path write_array_script(const RegressArgs& a, const RegressOptions& o, size_t tests) {
  const fs::path dir = o.out / "slurm";
  fs::create_directories(dir);
  const fs::path script = dir / "array.sh";
  const int minutes = static_cast<int>(a.timeout / 60) + 2;  // the test's timeout, and a margin
  const std::string text = fmt::format(
      "#!/bin/bash\n"
      "# texsim regress {} on Slurm: one array task per test; `texsim regress --merge` joins "
      "them.\n"
      "#SBATCH --job-name=texsim-regress\n"
      "#SBATCH --array=0-{}%{}\n"
      "#SBATCH --cpus-per-task=1\n"
      "#SBATCH --time={}\n"
      "#SBATCH --output={}/task_%a.out\n"
      "exec {} regress {} --out {} --timeout {} --task \"$SLURM_ARRAY_TASK_ID\"\n",
      a.list, tests - 1, o.jobs, minutes, dir.string(), command_line({o.texsim}),
      command_line({fs::absolute(a.list).string()}), command_line({o.out.string()}), a.timeout);
  write_file_atomically(script.string(), text);
  fs::permissions(script, fs::perms::owner_exec, fs::perm_options::add);
  return script;
}

// Submits the array; returns false when sbatch itself failed (not a test).
bool submit(const RegressArgs& a, const RegressOptions& o, size_t tests) {
  const fs::path script = write_array_script(a, o, tests);
  std::string command = a.sbatch + (a.no_wait ? "" : " --wait");
  if (!a.sbatch_args.empty()) command += " " + a.sbatch_args;
  command += " " + command_line({script.string()});
  fmt::print("regression {}: {} tests as a Slurm job array ({} at a time): {}\n", a.list, tests,
             o.jobs, command);
  std::fflush(stdout);
  const int status = std::system(command.c_str());
  // sbatch --wait exits with the array's highest exit code: a failing test's 1 is the merge's to
  // report; anything else is sbatch's own failure.
  return status != -1 && WIFEXITED(status) && WEXITSTATUS(status) <= (a.no_wait ? 0 : 1);
}

int run(const RegressArgs& a) {
  const std::vector<RegressTest> tests = read_regress_list(a.list);
  RegressOptions o;
  o.texsim = self();
  o.out = fs::absolute(a.out);
  o.jobs =
      a.jobs > 0 ? a.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.timeout_s = a.timeout;
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  if (a.task) {  // one array task: its test alone, its result in a file
    if (*a.task >= tests.size()) {
      throw InputError(a.list, "--task",
                       fmt::format("{} is beyond the list's {} tests", *a.task, tests.size()));
    }
    o.jobs = 1;
    const RegressResult r = run_regression({tests[*a.task]}, o).front();
    write_result_file(o, r);
    report_line(r);
    return r.passed() ? 0 : 1;
  }
  if (a.slurm) {
    if (!submit(a, o, tests.size())) {
      fmt::print(stderr, "texsim regress: {} failed; the results so far are merged\n", a.sbatch);
      // The usual cause: no configuration, which sbatch reports only as a DNS lookup failure.
      if (!std::getenv("SLURM_CONF")) {
        fmt::print(stderr,
                   "texsim regress: SLURM_CONF is not set; for the single-node Slurm of "
                   "scripts/slurm_local.sh: export SLURM_CONF=/tmp/tmu_slurm/slurm.conf\n");
      }
    }
    if (a.no_wait) {
      fmt::print("when the array has run: texsim regress {} --out {} --merge\n", a.list,
                 o.out.string());
      return 0;
    }
  }
  if (a.merge || a.slurm) {
    std::vector<RegressResult> results;
    for (const RegressTest& t : tests) results.push_back(read_result_file(o, t));
    return report(a, o, results, elapsed());
  }
  fmt::print("regression {}: {} tests on {} jobs, outputs in {}\n", a.list, tests.size(), o.jobs,
             o.out.string());
  std::fflush(stdout);
  const std::vector<RegressResult> results = run_regression(tests, o, report_line);
  for (const RegressResult& r : results) write_result_file(o, r);
  return report(a, o, results, elapsed());
}

}  // namespace

void add_regress_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "regress",
      "Run a regression list: `cosim BLOCK [--seeds A..B] [options]` and `render SCENE "
      "[options]` lines, each test a texsim process, --jobs at a time on this machine or as a "
      "Slurm job array (--slurm); writes OUT/junit.xml, OUT/summary.txt (each failure's "
      "reproduce command, waveform and log) and OUT/logs/. Exit 0 all passed, 1 a test failed, "
      "2 a bad list (docs/regress.md)");
  auto a = std::make_shared<RegressArgs>();
  cmd->add_option("list", a->list, "The regression list")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", a->out, "Where the logs, waveforms, renders and reports go")
      ->capture_default_str();
  cmd->add_option("--jobs,-j", a->jobs, "Tests at a time (default: the cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--timeout", a->timeout, "Seconds after which a test is killed and fails")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_flag("--slurm", a->slurm,
                "Run the tests as a Slurm job array (OUT/slurm/array.sh, submitted with sbatch "
                "--wait, --jobs tasks at a time), then merge their results");
  cmd->add_option("--sbatch", a->sbatch, "The sbatch to submit with")->capture_default_str();
  cmd->add_option("--sbatch-args", a->sbatch_args,
                  "More sbatch options, e.g. \"--partition=sim --account=hw\"");
  cmd->add_flag("--no-wait", a->no_wait, "With --slurm: submit and return; --merge later");
  cmd->add_flag("--merge", a->merge,
                "Only merge the results of an earlier run (OUT/results/) into the reports");
  cmd->add_option("--task", a->task, "Run only test I of the list (0-based): an array task");
  cmd->callback([a, &exit_code] { exit_code.value = run(*a); });
}

}  // namespace tmu::texsim
