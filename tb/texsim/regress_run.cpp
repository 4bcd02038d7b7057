#include "texsim/regress_run.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace tmu::texsim {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The test's command with the places of its outputs.
std::vector<std::string> command_of(const RegressTest& t, const RegressOptions& o) {
  std::vector<std::string> c = {o.texsim};
  c.insert(c.end(), t.args.begin(), t.args.end());
  if (t.kind == "cosim") {
    c.insert(c.end(), {"--wave-dir", (o.out / "waves" / t.name).string()});
  } else {
    c.insert(c.end(), {"--out", (o.out / "renders" / t.name).string()});
  }
  return c;
}

pid_t spawn(const std::vector<std::string>& command, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> argv;
  for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // A process group of its own: a timeout kills the test and every process it started (an hls
  // run forks a child).
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error("regress: cannot start " + command[0]);
  return pid;
}

std::vector<fs::path> waveforms_in(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().extension() == ".fst") out.push_back(e.path());
  }
  return out;
}

// Where the test's outputs go, and the waveforms found there.
fs::path output_dir(const RegressOptions& o, const RegressTest& t) {
  return o.out / (t.kind == "cosim" ? "waves" : "renders") / t.name;
}

}  // namespace

void write_result_file(const RegressOptions& options, const RegressResult& r) {
  fs::create_directories(options.out / "results");
  std::ofstream f(options.out / "results" / (r.test.name + ".txt"));
  f << "exit_code " << r.exit_code << "\nseconds " << r.seconds << "\ntimed_out "
    << (r.timed_out ? 1 : 0) << "\n";
}

RegressResult read_result_file(const RegressOptions& options, const RegressTest& test) {
  RegressResult r;
  r.test = test;
  r.command = command_of(test, options);
  r.log = options.out / "logs" / (test.name + ".log");
  r.exit_code = -1;
  std::ifstream f(options.out / "results" / (test.name + ".txt"));
  for (std::string key; f >> key;) {
    if (key == "exit_code") f >> r.exit_code;
    if (key == "seconds") f >> r.seconds;
    if (key == "timed_out") {
      int t = 0;
      f >> t;
      r.timed_out = t != 0;
    }
  }
  r.waveforms = waveforms_in(output_dir(options, test));
  return r;
}

std::vector<RegressResult> run_regression(const std::vector<RegressTest>& tests,
                                          const RegressOptions& options,
                                          void (*progress)(const RegressResult&)) {
  fs::create_directories(options.out / "logs");
  std::vector<RegressResult> results(tests.size());
  struct Running {
    size_t index;
    Clock::time_point start;
  };
  std::map<pid_t, Running> running;
  size_t next = 0, done = 0;
  while (done < tests.size()) {
    while (next < tests.size() && static_cast<int>(running.size()) < options.jobs) {
      RegressResult& r = results[next];
      r.test = tests[next];
      r.command = command_of(r.test, options);
      r.log = options.out / "logs" / (r.test.name + ".log");
      running[spawn(r.command, r.log)] = {next, Clock::now()};
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid <= 0) {
      for (const auto& [p, run] : running) {
        const double s = std::chrono::duration<double>(Clock::now() - run.start).count();
        if (s > options.timeout_s && !results[run.index].timed_out) {
          results[run.index].timed_out = true;
          kill(-p, SIGKILL);
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      continue;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    RegressResult& r = results[it->second.index];
    r.seconds = std::chrono::duration<double>(Clock::now() - it->second.start).count();
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (r.timed_out) r.exit_code = -1;
    r.waveforms = waveforms_in(output_dir(options, r.test));
    running.erase(it);
    ++done;
    if (progress) progress(r);
  }
  return results;
}

}  // namespace tmu::texsim
