#include "scene/json_node.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <vector>

#include "common/error.hpp"

namespace tmu::host {
namespace {

std::string list_names(std::initializer_list<std::string_view> names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// JSON type names as a user would write them.
std::string type_name(const Json& j) {
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_array()) return "a list";
  if (j.is_object()) return "an object";
  return "null";
}

// Tracks where the parser is, so that a duplicated key (which nlohmann would silently resolve)
// is reported with its path, and so is a number nlohmann cannot hold (1e999), whose error
// carries no position.
class ParsePath {
 public:
  explicit ParsePath(const std::string& file) : file_(file) {}

  bool operator()(Json::parse_event_t event, Json& parsed) {
    using E = Json::parse_event_t;
    switch (event) {
      case E::object_start:
        begin_element();
        stack_.push_back({false, {}, -1, {}});
        break;
      case E::array_start:
        begin_element();
        stack_.push_back({true, {}, -1, {}});
        break;
      case E::object_end:
      case E::array_end:
        stack_.pop_back();
        break;
      case E::key: {
        Frame& f = stack_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) throw InputError(file_, path(false), "duplicate key");
        break;
      }
      case E::value:
        begin_element();
        break;
    }
    return true;
  }

  // The path of the last element begun, or (`next`) of the value the parser is reading when
  // it stops inside a value: a list's next element (an object's key is already set).
  std::string path(bool next) const {
    std::string p;
    for (size_t i = 0; i < stack_.size(); ++i) {
      const Frame& f = stack_[i];
      const long index = f.index + (next && i + 1 == stack_.size() ? 1 : 0);
      p = f.array ? element_path(p, static_cast<size_t>(index)) : join_path(p, f.key);
    }
    return p;
  }

 private:
  struct Frame {
    bool array;
    std::string key;  // objects: the current key
    long index;       // arrays: the current element
    std::set<std::string> keys;
  };

  void begin_element() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
  }

  const std::string& file_;
  std::vector<Frame> stack_;
};

// nlohmann's message without its "[json.exception.out_of_range.406] " prefix.
std::string without_prefix(const std::string& what) {
  const size_t end = what.starts_with("[json.exception.") ? what.find("] ") : std::string::npos;
  return end == std::string::npos ? what : what.substr(end + 2);
}

}  // namespace

std::string join_path(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string element_path(const std::string& path, size_t index) {
  return fmt::format("{}[{}]", path, index);
}

Json parse_json(const std::string& text, const std::string& file) {
  ParsePath where(file);
  try {
    return Json::parse(text, [&where](int /*depth*/, Json::parse_event_t event, Json& parsed) {
      return where(event, parsed);
    });
  } catch (const Json::parse_error& e) {
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 3, column 7:
    // syntax error while parsing ..."; keep the position as the field and the rest as reason.
    const std::string what = e.what();
    const size_t at = what.find("line ");
    const size_t colon = at == std::string::npos ? at : what.find(": ", at);
    if (colon == std::string::npos) throw InputError(file, "", what);
    throw InputError(file, what.substr(at, colon - at), what.substr(colon + 2));
  } catch (const Json::out_of_range& e) {
    // A number beyond a double (1e999): nlohmann gives no position, the path names the value.
    throw InputError(file, where.path(true), without_prefix(e.what()));
  } catch (const Json::exception& e) {
    throw InputError(file, "", without_prefix(e.what()));
  }
}

void JsonNode::fail(const std::string& reason) const { throw InputError(*file_, path_, reason); }

JsonNode JsonNode::child(std::string_view key, const Json& value) const {
  return JsonNode(value, join_path(path_, key), *file_);
}

void JsonNode::expect_object() const {
  if (!value_->is_object()) fail("expected an object, got " + type_name(*value_));
}

void JsonNode::allow_keys(std::initializer_list<std::string_view> allowed) const {
  expect_object();
  for (const auto& [key, value] : value_->items()) {
    bool ok = false;
    for (std::string_view a : allowed) ok = ok || a == key;
    if (!ok) child(key, value).fail("unknown key (expected one of: " + list_names(allowed) + ")");
  }
}

bool JsonNode::has(std::string_view key) const {
  expect_object();
  return value_->contains(key);
}

JsonNode JsonNode::at(std::string_view key) const {
  expect_object();
  const auto it = value_->find(key);
  if (it == value_->end())
    JsonNode(*value_, join_path(path_, key), *file_).fail("missing required key");
  return child(key, *it);
}

std::optional<JsonNode> JsonNode::find(std::string_view key) const {
  expect_object();
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return child(key, *it);
}

void JsonNode::expect_array() const {
  if (!value_->is_array()) fail("expected a list, got " + type_name(*value_));
}

size_t JsonNode::size() const {
  expect_array();
  return value_->size();
}

JsonNode JsonNode::operator[](size_t i) const {
  return JsonNode((*value_)[i], element_path(path_, i), *file_);
}

double JsonNode::positive() const {
  const double v = number();
  if (!(v > 0)) fail("must be > 0");
  return v;
}

double JsonNode::number() const {
  if (!value_->is_number()) fail("expected a number, got " + type_name(*value_));
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("number out of range");
  return v;
}

int64_t JsonNode::integer(int64_t lo, int64_t hi) const {
  const std::string range = fmt::format("must be an integer in {}..{}", lo, hi);
  if (!value_->is_number()) fail("expected an integer, got " + type_name(*value_));
  if (value_->is_number_unsigned()) {
    const auto u = value_->get<uint64_t>();
    if (u > static_cast<uint64_t>(hi) || static_cast<int64_t>(u) < lo) fail(range);
    return static_cast<int64_t>(u);
  }
  if (value_->is_number_integer()) {
    const auto i = value_->get<int64_t>();
    if (i < lo || i > hi) fail(range);
    return i;
  }
  // A float is accepted when it is a whole number in range (320.0).
  const double d = number();
  if (d != std::floor(d)) fail("expected an integer, got " + value_->dump());
  if (d < static_cast<double>(lo) || d > static_cast<double>(hi)) fail(range);
  return static_cast<int64_t>(d);
}

std::string JsonNode::string() const {
  if (!value_->is_string()) fail("expected a string, got " + type_name(*value_));
  return value_->get<std::string>();
}

std::string JsonNode::one_of(std::initializer_list<std::string_view> names) const {
  const std::string s = string();
  for (std::string_view n : names) {
    if (n == s) return s;
  }
  fail("unknown value '" + s + "' (expected one of: " + list_names(names) + ")");
}

void JsonNode::expect_numbers(size_t n) const {
  const std::string want = fmt::format("expected a list of {} numbers", n);
  if (!value_->is_array()) fail(want + ", got " + type_name(*value_));
  if (value_->size() != n) fail(fmt::format("{}, got {}", want, value_->size()));
}

glm::dvec2 JsonNode::vec2() const {
  expect_numbers(2);
  return {(*this)[0].number(), (*this)[1].number()};
}

glm::dvec3 JsonNode::vec3() const {
  expect_numbers(3);
  return {(*this)[0].number(), (*this)[1].number(), (*this)[2].number()};
}

glm::dvec4 JsonNode::vec4() const {
  expect_numbers(4);
  return {(*this)[0].number(), (*this)[1].number(), (*this)[2].number(), (*this)[3].number()};
}

namespace {
void check_component(const JsonNode& n, double v, double lo, double hi) {
  if (hi < 0 && v < lo) n.fail(fmt::format("must be >= {}", lo));
  if (hi >= 0 && (v < lo || v > hi)) n.fail(fmt::format("must be in {}..{}", lo, hi));
}
}  // namespace

glm::dvec3 JsonNode::colour3(double lo, double hi) const {
  const glm::dvec3 c = vec3();
  for (int i = 0; i < 3; ++i) check_component((*this)[static_cast<size_t>(i)], c[i], lo, hi);
  return c;
}

glm::dvec4 JsonNode::colour4(double lo, double hi) const {
  const glm::dvec4 c = vec4();
  for (int i = 0; i < 4; ++i) check_component((*this)[static_cast<size_t>(i)], c[i], lo, hi);
  return c;
}

}  // namespace tmu::host
