#include "texsim/request_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "formats/formats.hpp"

namespace tmu::texsim {
namespace {

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(trim(c));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

bool parse_real(const std::string& s, double& v) {
  if (s.empty()) return false;
  const char* end = s.data() + s.size();
  auto [p, ec] = std::from_chars(s.data(), end, v);
  return ec == std::errc() && p == end && std::isfinite(v);
}

bool parse_rgba(const std::string& s, uint32_t& v) {
  const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
  const char* begin = s.data() + (hex ? 2 : 0);
  uint64_t x = 0;
  auto [p, ec] = std::from_chars(begin, s.data() + s.size(), x, hex ? 16 : 10);
  if (ec != std::errc() || p != s.data() + s.size() || x > 0xFFFFFFFFull) return false;
  v = static_cast<uint32_t>(x);
  return true;
}

// The largest magnitude a port format carries, in real units.
double port_limit(const fx::Format& f) {
  return std::ldexp(static_cast<double>(f.max_raw()), -f.frac_bits);
}

const std::vector<std::string> kColumns{"u",    "v",    "lambda", "shade",
                                        "dudx", "dvdx", "dudy",   "dvdy"};

}  // namespace

std::vector<SampleRequest> read_requests(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open request file");
  return read_requests(in, path);
}

std::vector<SampleRequest> read_requests(std::istream& in, const std::string& path) {
  std::vector<std::string> columns;
  std::vector<SampleRequest> requests;
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    if (trim(line).empty()) continue;
    const auto cells = cells_of(line);
    const auto where = [&](const std::string& col) {
      return fmt::format("line {}: {}", line_no, col);
    };
    if (columns.empty()) {
      double probe;
      if (!parse_real(cells[0], probe)) {  // a header
        for (size_t i = 0; i < cells.size(); ++i) {
          const std::string& c = cells[i];
          if (std::find(kColumns.begin(), kColumns.end(), c) == kColumns.end()) {
            throw InputError(
                path, where("header"),
                "unknown column '" + c + "' (u, v, lambda, shade, dudx, dvdx, dudy, dvdy)");
          }
          // A second 'u' would silently replace the first one's value.
          if (std::find(cells.begin(), cells.begin() + static_cast<long>(i), c) !=
              cells.begin() + static_cast<long>(i)) {
            throw InputError(path, where("header"), "duplicate column '" + c + "'");
          }
        }
        for (const char* needed : {"u", "v", "lambda"}) {
          if (std::find(cells.begin(), cells.end(), needed) == cells.end()) {
            throw InputError(path, where("header"), std::string("missing column '") + needed + "'");
          }
        }
        columns = cells;
        continue;
      }
      columns = {"u", "v", "lambda"};
    }
    if (cells.size() != columns.size()) {
      throw InputError(path, fmt::format("line {}", line_no),
                       fmt::format("{} values for {} columns ({})", cells.size(), columns.size(),
                                   fmt::join(columns, ",")));
    }
    SampleRequest r;
    std::array<double, 4> d{};
    bool has_d = false;
    for (size_t i = 0; i < cells.size(); ++i) {
      const std::string& col = columns[i];
      if (col == "shade") {
        if (!parse_rgba(cells[i], r.shade))
          throw InputError(path, where(col), "not an RGBA value like 0xFF8000FF");
        continue;
      }
      double v;
      if (!parse_real(cells[i], v))
        throw InputError(path, where(col), "'" + cells[i] + "' is not a number");
      const double limit = port_limit(col == "lambda" ? formats::kLod : formats::kTexCoord);
      if ((col == "u" || col == "v" || col == "lambda") && std::abs(v) > limit) {
        throw InputError(path, where(col),
                         fmt::format("{} is outside the port's range +-{}", v, limit));
      }
      if (col == "u") r.u = v;
      if (col == "v") r.v = v;
      if (col == "lambda") r.lambda = v;
      for (size_t k = 0; k < 4; ++k) {
        if (col == kColumns[4 + k]) {
          d[k] = v;
          has_d = true;
        }
      }
    }
    if (has_d) r.derivatives = d;
    requests.push_back(r);
  }
  if (requests.empty()) throw InputError(path, "", "no requests");
  return requests;
}

void write_results(const std::string& path, const std::vector<uint32_t>& rgba) {
  std::string out = "r,g,b,a\n";
  for (uint32_t c : rgba)
    out += fmt::format("{},{},{},{}\n", c >> 24, (c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF);
  write_file_atomically(path, out);
}

}  // namespace tmu::texsim
