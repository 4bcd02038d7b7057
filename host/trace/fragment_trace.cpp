#include "trace/fragment_trace.hpp"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <string_view>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "formats/formats.hpp"

namespace tmu::host {
namespace {

constexpr std::string_view kHeader =
    "x,y,material,u,v,lambda,shade,r1u,r1v,r2u,r2v,su,sv,sw,nx,ny,nz,vx,vy,vz";
constexpr size_t kColumns = 20;

// The format of each column, in header order.
constexpr std::array<fx::Format, kColumns> kColumnFormats = {
    formats::kPixelCoord, formats::kPixelCoord, formats::kMaterialId, formats::kTexCoord,
    formats::kTexCoord,   formats::kLod,        formats::kRgba8888,   formats::kTexDeriv,
    formats::kTexDeriv,   formats::kTexDeriv,   formats::kTexDeriv,   formats::kSolidCoord,
    formats::kSolidCoord, formats::kSolidCoord, formats::kUnitComp,   formats::kUnitComp,
    formats::kUnitComp,   formats::kUnitComp,   formats::kUnitComp,   formats::kUnitComp};
constexpr size_t kShadeColumn = 6;

std::array<int64_t, kColumns> columns_of(const FragmentRecord& r) {
  return {r.x,         r.y,         r.material,  r.u,       r.v,        r.lambda,   r.shade,
          r.r1[0],     r.r1[1],     r.r2[0],     r.r2[1],   r.solid[0], r.solid[1], r.solid[2],
          r.normal[0], r.normal[1], r.normal[2], r.view[0], r.view[1],  r.view[2]};
}

FragmentRecord record_of(const std::array<int64_t, kColumns>& c) {
  FragmentRecord r;
  r.x = static_cast<uint16_t>(c[0]);
  r.y = static_cast<uint16_t>(c[1]);
  r.material = static_cast<uint8_t>(c[2]);
  r.u = static_cast<int32_t>(c[3]);
  r.v = static_cast<int32_t>(c[4]);
  r.lambda = static_cast<int32_t>(c[5]);
  r.shade = static_cast<uint32_t>(c[6]);
  for (size_t i = 0; i < 2; ++i) {
    r.r1[i] = static_cast<int32_t>(c[7 + i]);
    r.r2[i] = static_cast<int32_t>(c[9 + i]);
  }
  for (size_t i = 0; i < 3; ++i) {
    r.solid[i] = static_cast<int32_t>(c[11 + i]);
    r.normal[i] = static_cast<int16_t>(c[14 + i]);
    r.view[i] = static_cast<int16_t>(c[17 + i]);
  }
  return r;
}

std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == sep) {
      out.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

std::string_view column_name(size_t i) { return split(kHeader, ',')[i]; }

class TraceReader {
 public:
  explicit TraceReader(std::string path) : path_(std::move(path)) {}

  FragmentTrace read(std::istream& in) {
    std::string text;
    bool header = false;
    while (std::getline(in, text)) {
      ++line_;
      std::string_view line = text;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (line.empty()) continue;
      if (line.front() == '#') {
        if (!header) comment(line);
        continue;
      }
      if (!header) {
        if (line != kHeader) fail("", fmt::format("expected the header '{}'", kHeader));
        if (trace_.width == 0) fail("", "missing the '# frame: WxH' comment before the header");
        header = true;
        continue;
      }
      record(line);
    }
    if (in.bad()) throw InputError(path_, "", "read error");
    if (!header) throw InputError(path_, "", fmt::format("no header line '{}'", kHeader));
    return std::move(trace_);
  }

 private:
  [[noreturn]] void fail(const std::string& column, const std::string& reason) const {
    throw InputError(path_, fmt::format("line {}{}", line_, column), reason);
  }

  void comment(std::string_view line) {
    constexpr std::string_view kScene = "# scene: ", kFrame = "# frame: ";
    if (line.starts_with(kScene)) {
      trace_.scene = std::string(line.substr(kScene.size()));
    } else if (line.starts_with(kFrame)) {
      const std::vector<std::string_view> wh = split(line.substr(kFrame.size()), 'x');
      int size[2] = {0, 0};
      for (size_t i = 0; wh.size() == 2 && i < 2; ++i) {
        const auto [end, ec] = std::from_chars(wh[i].data(), wh[i].data() + wh[i].size(), size[i]);
        if (ec != std::errc() || end != wh[i].data() + wh[i].size()) size[i] = 0;
      }
      if (size[0] < 1 || size[1] < 1 || size[0] > formats::kMaxTexSize ||
          size[1] > formats::kMaxTexSize) {
        fail("", fmt::format("bad frame comment '{}' (expected '# frame: WxH', 1..{})", line,
                             formats::kMaxTexSize));
      }
      trace_.width = size[0];
      trace_.height = size[1];
    }
  }

  void record(std::string_view line) {
    const std::vector<std::string_view> fields = split(line, ',');
    if (fields.size() != kColumns) {
      fail("", fmt::format("expected {} columns, got {}", kColumns, fields.size()));
    }
    std::array<int64_t, kColumns> c{};
    for (size_t i = 0; i < kColumns; ++i) {
      const std::string where = fmt::format(", column {} ({})", i + 1, column_name(i));
      c[i] = value(fields[i], i == kShadeColumn, where);
      const fx::Format& f = kColumnFormats[i];
      if (!f.holds(c[i])) {
        fail(where, fmt::format("{} is outside {} ({}..{})", c[i], fx::to_string(f), f.min_raw(),
                                f.max_raw()));
      }
    }
    for (size_t i = 0; i < 2; ++i) {
      if (c[i] >= (i == 0 ? trace_.width : trace_.height)) {
        fail(fmt::format(", column {} ({})", i + 1, column_name(i)),
             fmt::format("pixel ({}, {}) is outside the {}x{} frame", c[0], c[1], trace_.width,
                         trace_.height));
      }
    }
    trace_.records.push_back(record_of(c));
  }

  int64_t value(std::string_view s, bool hex, const std::string& where) const {
    std::string_view digits = s;
    int base = 10;
    if (hex) {
      if (!(s.starts_with("0x") || s.starts_with("0X")))
        fail(where, fmt::format("expected 0xRRGGBBAA, got '{}'", s));
      digits.remove_prefix(2);
      base = 16;
    }
    int64_t v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, base);
    if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() ||
        (hex && digits.front() == '-')) {
      fail(where, fmt::format("expected {}, got '{}'", hex ? "0xRRGGBBAA" : "an integer", s));
    }
    return v;
  }

  std::string path_;
  size_t line_ = 0;
  FragmentTrace trace_;
};

}  // namespace

void write_trace(const std::string& path, const FragmentTrace& trace) {
  write_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "", std::string("cannot create: ") + std::strerror(errno));
    // A line break in the scene path would end the comment early.
    std::string scene = trace.scene;
    for (char& ch : scene) ch = (ch == '\n' || ch == '\r') ? ' ' : ch;
    fmt::memory_buffer buf;
    fmt::format_to(std::back_inserter(buf),
                   "# fragment trace: one visible fragment per line, raw fixed-point values\n"
                   "# scene: {}\n# frame: {}x{}\n{}\n",
                   scene, trace.width, trace.height, kHeader);
    for (const FragmentRecord& r : trace.records) {
      const std::array<int64_t, kColumns> c = columns_of(r);
      for (size_t i = 0; i < kColumns; ++i) {
        if (i > 0) buf.push_back(',');
        if (i == kShadeColumn) {
          fmt::format_to(std::back_inserter(buf), "0x{:08X}", c[i]);
        } else {
          fmt::format_to(std::back_inserter(buf), "{}", c[i]);
        }
      }
      buf.push_back('\n');
      if (buf.size() > (1 << 20)) {
        out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
        buf.clear();
      }
    }
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    out.close();
    if (!out) throw InputError(path, "", "write failed (disk full?)");
  });
}

FragmentTrace read_trace(std::istream& in, const std::string& name) {
  return TraceReader(name).read(in);
}

FragmentTrace read_trace(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot open: ") + std::strerror(errno));
  return read_trace(in, path);
}

}  // namespace tmu::host
