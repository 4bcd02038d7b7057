#include "harness/vector_file.hpp"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace tmu::tb {
namespace {

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// Parses one cell into the field's bits; nullopt-like false on error with a reason.
bool parse_value(const std::string& text, const fx::Format& f, uint64_t& bits, std::string& why) {
  if (text.empty()) {
    why = "empty value";
    return false;
  }
  const char* b = text.data();
  const char* e = text.data() + text.size();
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    uint64_t v = 0;
    auto [p, ec] = std::from_chars(b + 2, e, v, 16);
    if (ec != std::errc() || p != e) {
      why = "not a hex number";
      return false;
    }
    if (f.width() < 64 && (v >> f.width()) != 0) {
      why = fmt::format("0x{:x} does not fit {} bits", v, f.width());
      return false;
    }
    bits = v;
    return true;
  }
  int64_t v = 0;
  auto [p, ec] = std::from_chars(b, e, v, 10);
  if (ec != std::errc() || p != e) {
    why = "not a number";
    return false;
  }
  if (!f.holds(v)) {
    why =
        fmt::format("{} is outside {} (raw {}..{})", v, fx::to_string(f), f.min_raw(), f.max_raw());
    return false;
  }
  bits =
      static_cast<uint64_t>(v) & (f.width() < 64 ? (uint64_t{1} << f.width()) - 1 : ~uint64_t{0});
  return true;
}

}  // namespace

std::vector<Txn> read_vectors(const std::string& path, const Schema& schema) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open vector file");
  std::vector<int> column_field;  // column -> schema field
  std::vector<Txn> items;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    if (trim(line).empty()) continue;
    const auto cells = split_csv(line);
    if (column_field.empty()) {
      for (const std::string& name : cells) {
        const int fi = schema.index(name);
        if (fi < 0) {
          std::string known;
          for (const Field& f : schema.fields()) known += (known.empty() ? "" : ", ") + f.name;
          throw InputError(path, fmt::format("line {}: header", line_no),
                           "unknown field '" + name + "' (fields: " + known + ")");
        }
        column_field.push_back(fi);
      }
      continue;
    }
    if (cells.size() != column_field.size()) {
      throw InputError(
          path, fmt::format("line {}", line_no),
          fmt::format("{} values for {} header fields", cells.size(), column_field.size()));
    }
    // The op first (a block whose channels share the slots): it says which columns count;
    // the others hold "-".
    Txn t;
    for (int pass = 0; pass < 2; ++pass) {
      for (size_t c = 0; c < cells.size(); ++c) {
        const auto fi = static_cast<size_t>(column_field[c]);
        const Field& f = schema.field(fi);
        const bool is_op = f.name == "op" && f.slot == 0;
        if (is_op != (pass == 0)) continue;
        if (!schema.carries(fi, t)) continue;
        std::string why;
        if (!parse_value(cells[c], f.format, t.f[static_cast<size_t>(f.slot)], why)) {
          throw InputError(path, fmt::format("line {}: {}", line_no, f.name), why);
        }
      }
    }
    items.push_back(t);
  }
  if (column_field.empty()) throw InputError(path, "header", "no header line");
  return items;
}

void write_vectors(const std::string& path, const Schema& schema, const std::vector<Txn>& items) {
  std::string out;
  for (size_t f = 0; f < schema.size(); ++f) out += (f ? "," : "") + schema.fields()[f].name;
  out += '\n';
  for (const Txn& t : items) {
    for (size_t f = 0; f < schema.size(); ++f) {
      if (f) out += ',';
      out += schema.carries(f, t)
                 ? fmt::format("0x{:x}", t.f[static_cast<size_t>(schema.field(f).slot)])
                 : "-";
    }
    out += '\n';
  }
  write_file_atomically(path, out);
}

}  // namespace tmu::tb
