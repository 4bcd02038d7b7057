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

std::string mark_name(Mark mark) {
  switch (mark) {
    case Mark::kNone:
      return "";
    case Mark::kSim:
      return "sim";
    case Mark::kSynth:
      return "synth";
    case Mark::kSynthOnly:
      return "synth only";
    case Mark::kFormula:
      return "formula";
    case Mark::kModel:
      return "model";
  }
  return "";
}

std::string marks_legend() {
  return "- **[sim]**: measured on a hardware model (the Verilated RTL, Icarus Verilog or the "
         "SystemC hls model) whose outputs were compared bit for bit with golden in this run; the "
         "table's `= golden` column says on what and with which result.\n"
         "- **[synth]**: Yosys (`scripts/synth.sh`) on the RTL at the row's setting, RTL that a "
         "simulation in this run showed equal to golden at that setting.\n"
         "- **[synth only]**: Yosys on RTL that no simulation in this run showed equal to golden "
         "at that setting (mostly: the build has no model of it): the figures of a design nobody "
         "checked there.\n"
         "- **[formula]**: computed from the setting or from counts (table sizes, cycles from "
         "counted misses), not measured.\n"
         "- **[model]**: from a C++ model (golden, ideal, the page model's timing, OpenImageIO), "
         "not from the hardware; golden's outputs are the hardware's only where the row's "
         "`= golden` says yes.\n";
}

namespace {

// "cells [synth]": the text with its mark, unless it has none or the one it inherits.
std::string shown(const Marked& m, Mark inherited) {
  return m.mark == Mark::kNone || m.mark == inherited
             ? m.text
             : fmt::format("{} [{}]", m.text, mark_name(m.mark));
}

}  // namespace

std::vector<std::string> SweepTable::header_text() const {
  std::vector<std::string> out;
  for (const Column& c : columns_) out.push_back(shown(c, Mark::kNone));
  return out;
}

std::vector<std::string> SweepTable::row_text(const std::vector<Cell>& row) const {
  std::vector<std::string> out;
  for (size_t i = 0; i < row.size(); ++i)
    out.push_back(shown(row[i], i < columns_.size() ? columns_[i].mark : Mark::kNone));
  return out;
}

std::vector<std::vector<std::string>> SweepTable::rows_text() const {
  std::vector<std::vector<std::string>> out;
  for (const auto& r : rows_) out.push_back(row_text(r));
  return out;
}

std::string SweepTable::last_row_text() const {
  const auto rows = rows_text();
  return rows.empty() ? "" : line_of(rows.back(), widths_of(header_text(), rows));
}

void SweepTable::print(const std::string& markdown_path) const {
  const std::vector<std::string> header = header_text();
  const auto rows = rows_text();
  const auto w = widths_of(header, rows);
  fmt::print("\n{}\n", line_of(header, w));
  for (const auto& r : rows) fmt::print("{}\n", line_of(r, w));
  if (markdown_path.empty()) return;
  std::string md = "| " + fmt::format("{}", fmt::join(header, " | ")) + " |\n|";
  for (size_t i = 0; i < header.size(); ++i) md += "---|";
  md += "\n";
  for (const auto& r : rows) md += "| " + fmt::format("{}", fmt::join(r, " | ")) + " |\n";
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
  std::vector<std::string> names;
  for (const Column& c : columns_) names.push_back(c.text);
  csv_line(names);
  for (const auto& r : rows_) {
    std::vector<std::string> figures;
    for (const Cell& c : r) figures.push_back(c.text);
    csv_line(figures);
  }
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
  // The sweep reads the top's figures only: no per-submodule synthesis.
  std::string cmd =
      fmt::format("TMU_SYNTH_CACHE='{}' '{}/scripts/synth.sh' --figures --no-submodules",
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

Cell synth_cell(const std::string& figure, bool simulated) {
  if (figure == "-" || figure == "?" || figure == "n/a") return {figure};
  return {figure, simulated ? Mark::kSynth : Mark::kSynthOnly};
}

std::string RtlSpeed::text() const {
  return samples_per_second > 0 ? fmt::format("{:.2f}", samples_per_second / 1e6) : "-";
}

}  // namespace tmu::texsim
