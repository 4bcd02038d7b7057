#include "icarus/icarus_engine.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "common/fnv1a.hpp"
#include "common/read_file.hpp"

extern char** environ;

// Set by tb/icarus/icarus.cmake; empty when configure did not find the tool.
#ifndef TMU_IVERILOG
#define TMU_IVERILOG ""
#endif
#ifndef TMU_VVP
#define TMU_VVP ""
#endif
#ifndef TMU_ICARUS_CACHE_DIR
#define TMU_ICARUS_CACHE_DIR ""
#endif

namespace tmu::tb {
namespace {
namespace fs = std::filesystem;

// Bump when the rewrite or the compile flags change, so cached models are rebuilt.
constexpr std::string_view kCompileFlavour = "icarus-compat-1 -g2012 -DSYNTHESIS";

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("icarus: cannot write " + path.string());
}

// The last `max_lines` lines of a log file, for an error message.
std::string log_tail(const fs::path& path, size_t max_lines = 20) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string out;
  for (size_t i = lines.size() > max_lines ? lines.size() - max_lines : 0; i < lines.size(); ++i)
    out += "\n    " + lines[i];
  return out;
}

// Runs argv (no shell) with stdout and stderr to `log`; returns the exit status, or -1 if the
// program could not be started or did not exit normally.
int run_process(const std::vector<std::string>& argv, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path cache_dir() {
  if (const char* env = std::getenv("TMU_ICARUS_CACHE"); env != nullptr && *env != '\0') return env;
  if (std::string_view(TMU_ICARUS_CACHE_DIR).empty())
    return fs::temp_directory_path() / "tmu-icarus";
  return TMU_ICARUS_CACHE_DIR;
}

}  // namespace

// A row's items are .sv files or earlier rows' tops, which stand for their sources; each file
// comes once, where it first appears (the manifest's header; rtl/CMakeLists.txt and
// scripts/manifest_sources.sh resolve it the same way).
std::vector<std::string> manifest_sources(const std::string& top) {
  const fs::path rtl = fs::path(TMU_SOURCE_DIR) / "rtl";
  std::map<std::string, std::vector<std::string>> rows;  // every row, resolved
  std::istringstream manifest(read_file(rtl / "manifest.txt"));
  for (std::string line; std::getline(manifest, line);) {
    std::istringstream fields(line);
    std::string name;
    if (!(fields >> name) || name.starts_with("#")) continue;
    if (rows.contains(name))
      throw std::runtime_error("rtl/manifest.txt: " + name + " has two rows");
    std::vector<std::string> sources;
    const auto add = [&sources](const std::string& file) {
      if (std::find(sources.begin(), sources.end(), file) == sources.end()) sources.push_back(file);
    };
    for (std::string item; fields >> item;) {
      if (item.ends_with(".sv")) {
        add(item);
      } else if (const auto row = rows.find(item); row != rows.end()) {
        for (const std::string& file : row->second) add(file);
      } else {
        throw std::runtime_error("rtl/manifest.txt: " + name + ": " + item +
                                 " is neither a .sv file nor the top of an earlier row");
      }
    }
    rows.emplace(name, std::move(sources));
  }
  const auto row = rows.find(top);
  if (row == rows.end()) throw std::runtime_error(top + " is not a top of rtl/manifest.txt");
  std::vector<std::string> sources = {"tmu_pkg.sv"};
  sources.insert(sources.end(), row->second.begin(), row->second.end());
  return sources;
}

std::string icarus_compat_source(const std::string& file, const std::string& text) {
  // Rule 3 (the package): the value of every `localparam int unsigned NameW = <number>;`,
  // substituted into the typedef ranges `[NameW-1:0]`.
  std::string out = text;
  if (fs::path(file).filename() == "tmu_pkg.sv") {
    static const std::regex value_re(
        R"(localparam\s+int\s+unsigned\s+([A-Za-z_][A-Za-z0-9_]*)\s*=\s*([0-9]+)\s*;)");
    std::vector<std::pair<std::string, std::string>> values;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), value_re);
         it != std::sregex_iterator(); ++it)
      values.emplace_back((*it)[1].str(), (*it)[2].str());
    std::string lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
      if (line.find("typedef") != std::string::npos) {
        for (const auto& [name, value] : values) {
          const std::string from = "[" + name + "-1:0]";
          if (const size_t at = line.find(from); at != std::string::npos)
            line.replace(at, from.size(), "[" + value + "-1:0]");
        }
      }
      lines += line + "\n";
    }
    out = lines;
  }
  // Rule 1: `int unsigned` parameters as `bit [31:0]`.
  static const std::regex param_re(R"(\b(localparam|parameter)(\s+)int\s+unsigned\b)");
  out = std::regex_replace(out, param_re, "$1$2bit [31:0]");
  // Rule 2: elaboration-time severity tasks alone on their line as initial blocks.
  static const std::regex error_re(R"((^|\n)([ \t]*)\$(error|fatal)\()");
  out = std::regex_replace(out, error_re, "$1$2initial $$$3(");
  return out;
}

std::string icarus_compile(const IcarusModel& model, double* compile_seconds) {
  if (compile_seconds != nullptr) *compile_seconds = 0.0;
  const std::string iverilog = TMU_IVERILOG;
  if (iverilog.empty()) {
    throw std::runtime_error(
        "icarus: iverilog not found (install the Debian package iverilog, then re-run cmake)");
  }
  const fs::path root = TMU_SOURCE_DIR;
  const fs::path rtl = root / "rtl";
  const fs::path tb = root / "tb" / "icarus";

  // The rewritten sources (the mutation applied first, to the original text).
  std::vector<std::pair<std::string, std::string>> files;  // path in the model dir, text
  bool mutated = false;
  for (const std::string& rel : manifest_sources(model.top)) {
    std::string text = read_file(rtl / rel);
    if (model.mutation && model.mutation->file == rel) {
      const size_t at = text.find(model.mutation->from);
      if (at == std::string::npos) {
        throw std::runtime_error("icarus: mutation of " + rel +
                                 " did not apply: its text is gone; update the test");
      }
      text.replace(at, model.mutation->from.size(), model.mutation->to);
      mutated = true;
    }
    files.emplace_back("rtl/" + rel, icarus_compat_source(rel, text));
  }
  if (model.mutation && !mutated) {
    throw std::runtime_error("icarus: mutation names " + model.mutation->file +
                             ", not a source of " + model.top);
  }
  files.emplace_back("tb/stream_tb.svh", read_file(tb / "stream_tb.svh"));
  files.emplace_back("tb/" + model.testbench + ".sv", model.text);

  uint64_t h = kFnv1aBasis;
  h = fnv1a(h, kCompileFlavour);
  h = fnv1a(h, iverilog);
  h = fnv1a(h, model.testbench);
  h = fnv1a(h, model.top);
  for (const auto& [path, text] : files) h = fnv1a(fnv1a(h, path), text);
  const fs::path cache = cache_dir();
  const fs::path dir = cache / fmt::format("{}-{:016x}", model.testbench, h);
  const fs::path vvp = dir / "model.vvp";
  if (fs::exists(vvp)) return vvp.string();

  // Compile into a private directory, then rename it into place (another process may be
  // compiling the same model at the same time; the first rename wins, both are the same).
  const fs::path tmp = cache / fmt::format("{}.tmp-{}", dir.filename().string(), ::getpid());
  fs::remove_all(tmp);
  std::vector<std::string> argv = {iverilog,      "-g2012",
                                   "-DSYNTHESIS", "-DTMU_DUT=" + model.top,
                                   "-I",          (tmp / "tb").string(),
                                   "-o",          (tmp / "model.vvp").string(),
                                   "-s",          model.testbench};
  for (const auto& [path, text] : files) {
    write_text(tmp / path, text);
    if (!path.ends_with(".svh")) argv.push_back((tmp / path).string());
  }
  const auto start = std::chrono::steady_clock::now();
  const int rc = run_process(argv, tmp / "iverilog.log");
  if (compile_seconds != nullptr) {
    *compile_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (rc != 0 || !fs::exists(tmp / "model.vvp")) {
    throw std::runtime_error(
        fmt::format("icarus: iverilog could not compile {} (exit {}; sources and log in {}):{}",
                    model.top, rc, tmp.string(), log_tail(tmp / "iverilog.log")));
  }
  std::error_code ec;
  fs::rename(tmp, dir, ec);
  if (ec) fs::remove_all(tmp, ec);  // another process put it there first
  if (!fs::exists(vvp)) throw std::runtime_error("icarus: cannot create " + vvp.string());
  return vvp.string();
}

namespace {

class IcarusEngine : public Engine {
 public:
  IcarusEngine(std::string name, IcarusModel model, const Schema& inputs, const Schema& outputs,
               ProducesOutput produces_output)
      : name_(std::move(name)),
        model_(std::move(model)),
        inputs_(inputs),
        outputs_(outputs),
        produces_output_(std::move(produces_output)) {}

  std::string name() const override { return name_; }

  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    RunResult r;
    try {
      if (vvp_model_.empty()) vvp_model_ = icarus_compile(model_);
      simulate(items, options, r);
    } catch (const std::exception& e) {
      append(r, e.what());
    }
    return r;
  }

 private:
  static void append(RunResult& r, const std::string& error) {
    r.error += (r.error.empty() ? "" : "; ") + error;
  }

  void simulate(const std::vector<Txn>& items, const RunOptions& options, RunResult& r) {
    const std::string vvp = TMU_VVP;
    if (vvp.empty()) {
      throw std::runtime_error(
          "icarus: vvp not found (install the Debian package iverilog, then re-run cmake)");
    }
    std::string dir_template = (fs::temp_directory_path() / "tmu-icarus-run-XXXXXX").string();
    if (::mkdtemp(dir_template.data()) == nullptr)
      throw std::runtime_error("icarus: cannot create a temporary directory");
    const fs::path dir = dir_template;
    const fs::path in = dir / "in.txt", out = dir / "out.txt", log = dir / "vvp.log";

    size_t expected = 0;
    std::string text;
    text.reserve(items.size() * inputs_.size() * 9);
    for (const Txn& t : items) {
      if (!produces_output_ || produces_output_(t)) ++expected;
      const Txn m = inputs_.masked(t);
      for (size_t f = 0; f < inputs_.size(); ++f) {
        const uint64_t v = inputs_.carries(f, m) ? m.f[size_t(inputs_.field(f).slot)] : 0;
        fmt::format_to(std::back_inserter(text), "{}{:x}", f == 0 ? "" : " ", v);
      }
      text += '\n';
    }
    write_text(in, text);

    const auto permille = [](double p) { return std::to_string(std::lround(p * 1000.0)); };
    const std::vector<std::string> argv = {
        vvp,
        "-n",
        vvp_model_,
        "+in=" + in.string(),
        "+items=" + std::to_string(items.size()),
        "+out=" + out.string(),
        "+expected=" + std::to_string(expected),
        "+seed=" + std::to_string(1 + options.stalls.seed % 0x7FFFFFFEull),
        "+in_idle=" + permille(options.stalls.in_idle),
        "+out_stall=" + permille(options.stalls.out_stall),
        "+max_idle=" + std::to_string(options.max_idle_cycles)};
    const auto start = std::chrono::steady_clock::now();
    const int rc = run_process(argv, log);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    bool ok = rc == 0;
    if (!ok) append(r, fmt::format("vvp failed (exit {}):{}", rc, log_tail(log)));
    const std::string messages = read_file(log);
    if (ok && messages.find("ERROR") != std::string::npos) {
      append(r, "vvp reported an error:" + log_tail(log));
      ok = false;
    }
    if (ok) ok = parse_outputs(out, expected, r);
    if (ok) {
      fs::remove_all(dir);
    } else {
      append(r, "files in " + dir.string());
    }
  }

  // Reads the testbench's output file into r; false (with r.error) when the run failed.
  bool parse_outputs(const fs::path& path, size_t expected, RunResult& r) const {
    std::ifstream in(path);
    if (!in) {
      append(r, "vvp wrote no output file");
      return false;
    }
    r.outputs.reserve(expected);
    r.output_cycles.reserve(expected);
    bool finished = false;
    for (std::string line; std::getline(in, line);) {
      if (line.starts_with("# cycles ")) {
        r.cycles = std::stoull(line.substr(9));
        finished = true;
        continue;
      }
      if (line.starts_with("# error ")) {
        append(r, line.substr(8));
        return false;
      }
      if (line.find_first_of("xXzZ") != std::string::npos) {
        append(r, fmt::format("output {} has X or Z bits: \"{}\"", r.outputs.size(), line));
        return false;
      }
      const char* p = line.data();
      const char* end = p + line.size();
      uint64_t cycle = 0;
      std::from_chars_result read = std::from_chars(p, end, cycle);
      Txn t;
      for (size_t f = 0; read.ec == std::errc() && f < outputs_.size(); ++f) {
        while (read.ptr < end && *read.ptr == ' ') ++read.ptr;
        read = std::from_chars(read.ptr, end, t.f[f], 16);
      }
      if (read.ec != std::errc()) {
        append(r, fmt::format("cannot read output line \"{}\"", line));
        return false;
      }
      if (r.outputs.size() >= expected) {
        append(r, fmt::format("output {} at cycle {} is beyond the {} expected: a transaction "
                              "was duplicated",
                              r.outputs.size(), cycle, expected));
        return false;
      }
      r.outputs.push_back(outputs_.masked(t));
      r.output_cycles.push_back(cycle);
    }
    if (!finished) {
      append(r, fmt::format("the simulation ended after {} of {} outputs", r.outputs.size(),
                            expected));
      return false;
    }
    return true;
  }

  std::string name_;
  IcarusModel model_;
  Schema inputs_;
  Schema outputs_;
  ProducesOutput produces_output_;
  std::string vvp_model_;
};

}  // namespace

std::unique_ptr<Engine> make_icarus_engine(const std::string& name, IcarusModel model,
                                           const Schema& inputs, const Schema& outputs,
                                           ProducesOutput produces_output) {
  if (std::string_view(TMU_IVERILOG).empty() || std::string_view(TMU_VVP).empty()) {
    throw std::invalid_argument(
        "icarus: iverilog not found (install the Debian package iverilog, then re-run cmake)");
  }
  return std::make_unique<IcarusEngine>(name, std::move(model), inputs, outputs,
                                        std::move(produces_output));
}

}  // namespace tmu::tb
