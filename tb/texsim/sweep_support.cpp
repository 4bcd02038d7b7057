#include "texsim/sweep_support.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/fnv1a.hpp"
#include "common/read_file.hpp"

namespace tmu::texsim {
namespace {

std::vector<size_t> widths_of(const std::vector<std::string>& header,
                              const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> w;
  for (const auto& h : header) w.push_back(h.size());
  for (const auto& r : rows) {
    for (size_t i = 0; i < r.size() && i < w.size(); ++i) w[i] = std::max(w[i], r[i].size());
  }
  return w;
}

std::string line_of(const std::vector<std::string>& cells, const std::vector<size_t>& w) {
  std::string out;
  for (size_t i = 0; i < cells.size(); ++i) out += fmt::format("{:>{}}  ", cells[i], w[i]);
  return out;
}

}  // namespace

std::string SweepTable::last_row_text() const {
  return rows_.empty() ? "" : line_of(rows_.back(), widths_of(header_, rows_));
}

void SweepTable::print(const std::string& markdown_path) const {
  const auto w = widths_of(header_, rows_);
  fmt::print("\n{}\n", line_of(header_, w));
  for (const auto& r : rows_) fmt::print("{}\n", line_of(r, w));
  if (markdown_path.empty()) return;
  std::string md = "| " + fmt::format("{}", fmt::join(header_, " | ")) + " |\n|";
  for (size_t i = 0; i < header_.size(); ++i) md += "---|";
  md += "\n";
  for (const auto& r : rows_) md += "| " + fmt::format("{}", fmt::join(r, " | ")) + " |\n";
  write_file_atomically(markdown_path, md);
  std::string csv;
  auto csv_line = [&csv](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) {
      std::string quoted = cells[i];  // every cell quoted: settings such as 8,8,8 hold commas
      for (size_t at = quoted.find('"'); at != std::string::npos; at = quoted.find('"', at + 2))
        quoted.insert(at, 1, '"');
      csv += (i ? ",\"" : "\"") + quoted + "\"";
    }
    csv += "\n";
  };
  csv_line(header_);
  for (const auto& r : rows_) csv_line(r);
  const std::string csv_path = std::filesystem::path(markdown_path).replace_extension(".csv");
  write_file_atomically(csv_path, csv);
  fmt::print("wrote {} and {}\n", markdown_path, csv_path);
}

namespace {

// The content key of a synthesis: its command (top and parameters), the Yosys version, and
// the script and every RTL source (rtl/ is small; hashing it all is simpler than following
// the manifest).
uint64_t synth_key(const std::string& command) {
  namespace fs = std::filesystem;
  const fs::path root = TMU_SOURCE_DIR;
  uint64_t h = fnv1a(kFnv1aBasis, command);
  std::vector<fs::path> files = {root / "scripts/synth.sh"};
  for (const auto& e : fs::recursive_directory_iterator(root / "rtl"))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files)
    h = fnv1a(fnv1a(h, f.lexically_relative(root).string()), read_file(f));
  FILE* version = ::popen("yosys -V 2>&1", "r");
  std::array<char, 256> buf{};
  while (version != nullptr && std::fgets(buf.data(), buf.size(), version))
    h = fnv1a(h, buf.data());
  if (version != nullptr) ::pclose(version);
  return h;
}

SynthCounts counts;

}  // namespace

SynthCounts synth_counts() { return counts; }

SynthFigures synthesize(const std::string& top,
                        const std::vector<std::pair<std::string, int>>& params) {
  std::string cmd = std::string(TMU_SOURCE_DIR) + "/scripts/synth.sh";
  for (const auto& [name, value] : params) cmd += fmt::format(" -G {}={}", name, value);
  cmd += " " + top + " 2>&1";
  // A synthesis takes seconds to minutes and `texsim sweep all` runs dozens, most of them
  // unchanged since the last run: figures are kept per content key in the build directory.
  const std::filesystem::path cached =
      std::filesystem::path(TMU_SYNTH_CACHE_DIR) / fmt::format("{}-{:016x}", top, synth_key(cmd));
  if (SynthFigures hit; std::ifstream(cached) >> hit.cells >> hit.logic >> hit.depth) {
    ++counts.cached;
    return hit;
  }
  ++counts.run;
  SynthFigures f{"?", "?", "?"};
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return f;
  std::array<char, 512> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) {
    std::istringstream line(buf.data());
    std::string name, cells, flops, logic, mem, depth;
    if (line >> name >> cells >> flops >> logic >> mem >> depth && name == top)
      f = {cells, logic, depth};
  }
  if (::pclose(pipe) == 0 && f.cells != "?") {
    std::filesystem::create_directories(cached.parent_path());
    write_file_atomically(cached.string(), fmt::format("{} {} {}\n", f.cells, f.logic, f.depth));
  }
  return f;
}

std::string RtlSpeed::text() const {
  return samples_per_second > 0 ? fmt::format("{:.2f}", samples_per_second / 1e6) : "-";
}

}  // namespace tmu::texsim
