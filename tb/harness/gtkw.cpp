#include "harness/gtkw.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/atomic_file.hpp"

namespace tmu::tb {

void write_gtkw(const std::string& path, const std::string& fst_path,
                const std::vector<Port>& ports, uint64_t time_start, uint64_t time_end,
                uint64_t marker_time) {
  // Trace flags of the save format: 0x20 right-justify, 0x08 binary, 0x02 hex, 0x400 signed
  // decimal. Verilator puts the top module's ports in the scope TOP.
  std::string out = "[*] GTKWave save file written by texsim\n";
  out += fmt::format("[dumpfile] \"{}\"\n", std::filesystem::absolute(fst_path).string());
  out += fmt::format("[timestart] {}\n[size] 1600 900\n[pos] -1 -1\n", time_start);
  // GTKWave shows 200 * 2^zoom pixels per time unit (measured on 3.3.118); at [size] 1600 the
  // wave pane is about 1000 pixels wide, so this zoom fits the window with a small margin.
  const double span = static_cast<double>(std::max<uint64_t>(time_end - time_start, 1));
  const double zoom = -std::log2(span * 1.05 / 5.0);
  out += fmt::format("*{:.6f} {}", zoom, marker_time);
  for (int i = 0; i < 26; ++i) out += " -1";
  out += "\n[sst_width] 240\n[signals_width] 260\n[sst_expanded] 1\n";
  for (const Port& p : ports) {
    if (p.width == 1) {
      out += fmt::format("@28\nTOP.{}\n", p.name);
    } else {
      out += fmt::format("@{}\nTOP.{}[{}:0]\n", p.is_signed ? "424" : "22", p.name, p.width - 1);
    }
  }
  out += "[pattern_trace] 1\n[pattern_trace] 0\n";
  write_file_atomically(path, out);
}

}  // namespace tmu::tb
