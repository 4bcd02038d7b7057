// A JSON value together with its field path (`objects[2].transform.scale`) and the file it came
// from, so every check can report the file, the path and the reason as one InputError. The
// scene parser reads the document only through this class.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace tmu::host {

// ordered_json keeps the file's key order: materials are numbered in the order the file names
// them.
using Json = nlohmann::ordered_json;

// Parses `text`; a syntax error or a duplicated key is an InputError naming `file` and the line
// and column (syntax) or the path (duplicate key).
Json parse_json(const std::string& text, const std::string& file);

class JsonNode {
 public:
  JsonNode(const Json& value, std::string path, const std::string& file)
      : value_(&value), path_(std::move(path)), file_(&file) {}

  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  const Json& json() const { return *value_; }

  // Throws InputError(file, path, reason).
  [[noreturn]] void fail(const std::string& reason) const;

  // --- objects ---
  // Fails if this is not an object.
  void expect_object() const;
  // Fails on the first key not in `allowed`, naming it and the keys that are.
  void allow_keys(std::initializer_list<std::string_view> allowed) const;
  bool has(std::string_view key) const;
  JsonNode at(std::string_view key) const;  // "missing required key" when absent
  std::optional<JsonNode> find(std::string_view key) const;

  // --- arrays ---
  void expect_array() const;
  size_t size() const;  // of an array
  JsonNode operator[](size_t i) const;

  // --- scalars; each fails with "expected ..." on the wrong type ---
  double number() const;
  double positive() const;  // a number > 0: "must be > 0"
  // An integer in [lo, hi]; a number with a fraction is "expected an integer".
  int64_t integer(int64_t lo, int64_t hi) const;
  std::string string() const;
  // One of `names` (an error lists them).
  std::string one_of(std::initializer_list<std::string_view> names) const;

  // --- fixed-length number vectors: "expected N numbers", then per element ---
  glm::dvec2 vec2() const;
  glm::dvec3 vec3() const;
  glm::dvec4 vec4() const;
  // Colour components each in [lo, hi] (hi < 0: no upper bound); errors name the element.
  glm::dvec3 colour3(double lo, double hi) const;
  glm::dvec4 colour4(double lo, double hi) const;

 private:
  JsonNode child(std::string_view key, const Json& value) const;
  void expect_numbers(size_t n) const;

  const Json* value_;
  std::string path_;
  const std::string* file_;
};

// The path of a child: `a.b`, or `b` at the top.
std::string join_path(const std::string& path, std::string_view key);
std::string element_path(const std::string& path, size_t index);

}  // namespace tmu::host
