#include "texsim/sweep_support.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "common/atomic_file.hpp"

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

SynthCounts counts;

}  // namespace

SynthCounts synth_counts() { return counts; }

SynthFigures synthesize(const std::string& top,
                        const std::vector<std::pair<std::string, int>>& params) {
  // scripts/synth.sh --figures keeps every result by its content key (top, parameters, Yosys
  // version, script, sources), so a sweep rerun over unchanged RTL takes its figures from the
  // cache instead of minutes of Yosys; this build's cache is the one its tests and docs use.
  std::string cmd = fmt::format("TMU_SYNTH_CACHE='{}' '{}/scripts/synth.sh' --figures",
                                TMU_SYNTH_CACHE_DIR, TMU_SOURCE_DIR);
  for (const auto& [name, value] : params) cmd += fmt::format(" -G {}={}", name, value);
  cmd += " " + top + " 2>&1";
  SynthFigures f{"?", "?", "?"};
  bool cached = false;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return f;
  std::array<char, 512> buf{};
  const std::string cache_note = fmt::format("synth: {}: from cache", top);
  while (std::fgets(buf.data(), buf.size(), pipe)) {
    const std::string text = buf.data();
    if (text.starts_with(cache_note)) cached = true;
    std::istringstream line(text);
    std::string name, cells, flops, logic, mem, depth;
    if (line >> name >> cells >> flops >> logic >> mem >> depth && name == top)
      f = {cells, logic, depth};
  }
  ++(cached ? counts.cached : counts.run);
  if (::pclose(pipe) != 0) return {"?", "?", "?"};
  return f;
}

std::string RtlSpeed::text() const {
  return samples_per_second > 0 ? fmt::format("{:.2f}", samples_per_second / 1e6) : "-";
}

}  // namespace tmu::texsim
