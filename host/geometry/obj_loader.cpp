// Wavefront OBJ, the subset scenes use: v, vt, vn, f (polygons fanned from their first
// vertex), '#' comments; every other statement (o, g, s, usemtl, mtllib, l, ...) is skipped.
// Indices must refer to elements defined on earlier lines, as OBJ's negative (relative)
// indices presume.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "common/error.hpp"
#include "geometry/mesh.hpp"

namespace tmu::host {
namespace {

class ObjReader {
 public:
  explicit ObjReader(std::string path) : path_(std::move(path)) {}

  Mesh read() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw InputError(path_, "", "cannot open the OBJ file");
    std::string line;
    while (std::getline(in, line)) {
      ++line_no_;
      statement(line);
    }
    if (in.bad()) throw InputError(path_, "", "cannot read the OBJ file");
    if (faces_ == 0) throw InputError(path_, "", "no faces (f lines)");
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(path_, fmt::format("line {}", line_no_), reason);
  }

  static std::vector<std::string_view> split(std::string_view s) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
      const size_t start = i;
      while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != '\r') ++i;
      if (i > start) out.push_back(s.substr(start, i - start));
    }
    return out;
  }

  double number(std::string_view token) const {
    std::string_view t = token;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) {
      fail(fmt::format("expected a number, got '{}'", token));
    }
    return v;
  }

  // Numbers after the statement keyword: between `lo` and `hi` of them.
  std::vector<double> numbers(const std::vector<std::string_view>& tokens, size_t lo, size_t hi,
                              std::string_view what) const {
    const size_t n = tokens.size() - 1;
    if (n < lo || n > hi) {
      fail(lo == hi ? fmt::format("{} needs {} numbers, got {}", what, lo, n)
                    : fmt::format("{} needs {} to {} numbers, got {}", what, lo, hi, n));
    }
    std::vector<double> out;
    for (size_t i = 1; i < tokens.size(); ++i) out.push_back(number(tokens[i]));
    return out;
  }

  // A 1-based (or negative, relative) index into `count` elements; -1 when `token` is empty.
  long index(std::string_view token, size_t count, std::string_view what) const {
    if (token.empty()) return -1;
    long i = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), i);
    if (ec != std::errc() || end != token.data() + token.size()) {
      fail(fmt::format("expected a {} index, got '{}'", what, token));
    }
    const long resolved = i < 0 ? static_cast<long>(count) + i : i - 1;
    if (i == 0 || resolved < 0 || resolved >= static_cast<long>(count)) {
      fail(fmt::format("{} index {} out of range ({} {} defined so far)", what, i, count, what));
    }
    return resolved;
  }

  void statement(std::string_view line) {
    if (const size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    const std::vector<std::string_view> t = split(line);
    if (t.empty()) return;
    if (t[0] == "v") {
      // x y z, optionally w (homogeneous) or r g b (a common vertex-colour extension).
      const std::vector<double> v = numbers(t, 3, 6, "v");
      if (v.size() == 5) fail("v needs 3, 4 or 6 numbers, got 5");
      glm::dvec3 p(v[0], v[1], v[2]);
      if (v.size() == 4) {
        if (v[3] == 0) fail("v with w = 0 is a point at infinity");
        p /= v[3];
      }
      positions_.push_back(p);
    } else if (t[0] == "vt") {
      const std::vector<double> v = numbers(t, 1, 3, "vt");
      // OBJ's v = 0 is the bottom of the image, ours the top row: flip it.
      uvs_.push_back({v[0], 1.0 - (v.size() > 1 ? v[1] : 0.0)});
    } else if (t[0] == "vn") {
      const std::vector<double> v = numbers(t, 3, 3, "vn");
      const glm::dvec3 n(v[0], v[1], v[2]);
      if (glm::length(n) == 0) fail("vn is the zero vector");
      normals_.push_back(glm::normalize(n));
    } else if (t[0] == "f") {
      face(t);
    }
  }

  void face(const std::vector<std::string_view>& t) {
    if (t.size() < 4) fail(fmt::format("a face needs at least 3 vertices, got {}", t.size() - 1));
    struct Corner {
      long v, vt, vn;
    };
    std::vector<Corner> corners;
    for (size_t i = 1; i < t.size(); ++i) {
      std::string_view parts[3];
      size_t n = 0;
      size_t start = 0;
      for (size_t k = 0; k <= t[i].size(); ++k) {
        if (k == t[i].size() || t[i][k] == '/') {
          if (n == 3) fail(fmt::format("bad face vertex '{}' (v, v/vt, v//vn or v/vt/vn)", t[i]));
          parts[n++] = t[i].substr(start, k - start);
          start = k + 1;
        }
      }
      if (parts[0].empty()) fail(fmt::format("face vertex '{}' has no position index", t[i]));
      corners.push_back({index(parts[0], positions_.size(), "v"),
                         index(parts[1], uvs_.size(), "vt"),
                         index(parts[2], normals_.size(), "vn")});
    }
    ++faces_;
    // Newell's normal of the polygon: the face normal of corners without a vn.
    glm::dvec3 face_normal(0);
    for (size_t i = 0; i < corners.size(); ++i) {
      const glm::dvec3& a = positions_[static_cast<size_t>(corners[i].v)];
      const glm::dvec3& b = positions_[static_cast<size_t>(corners[(i + 1) % corners.size()].v)];
      face_normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                                (a.x - b.x) * (a.y + b.y));
    }
    const double len = glm::length(face_normal);
    face_normal = len > 0 ? face_normal / len : glm::dvec3(0, 1, 0);  // degenerate: culled anyway

    std::vector<uint32_t> ids;
    for (const Corner& c : corners) {
      if (c.vn < 0) {
        // A face normal belongs to this face only: not shared.
        ids.push_back(add({positions_[static_cast<size_t>(c.v)], face_normal, uv(c.vt)}));
        continue;
      }
      const auto key = std::make_tuple(c.v, c.vt, c.vn);
      auto it = shared_.find(key);
      if (it == shared_.end()) {
        it = shared_
                 .emplace(key, add({positions_[static_cast<size_t>(c.v)],
                                    normals_[static_cast<size_t>(c.vn)], uv(c.vt)}))
                 .first;
      }
      ids.push_back(it->second);
    }
    for (size_t i = 1; i + 1 < ids.size(); ++i)
      mesh_.triangles.push_back({ids[0], ids[i], ids[i + 1]});
  }

  glm::dvec2 uv(long vt) const { return vt < 0 ? glm::dvec2(0) : uvs_[static_cast<size_t>(vt)]; }

  uint32_t add(const Vertex& v) {
    mesh_.vertices.push_back(v);
    return static_cast<uint32_t>(mesh_.vertices.size() - 1);
  }

  std::string path_;
  size_t line_no_ = 0;
  size_t faces_ = 0;
  std::vector<glm::dvec3> positions_, normals_;
  std::vector<glm::dvec2> uvs_;
  std::map<std::tuple<long, long, long>, uint32_t> shared_;
  Mesh mesh_;
};

}  // namespace

Mesh load_obj(const std::string& path) { return ObjReader(path).read(); }

}  // namespace tmu::host
