// Errors a user can cause (a bad file, field or argument). The message always names the
// file, the field and the reason, so the CLI can print it as-is and exit non-zero.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace tmu {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& reason)
      : std::runtime_error(file + ": " + (field.empty() ? "" : field + ": ") + reason),
        file_(file),
        field_(field),
        reason_(reason) {}

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_, field_, reason_;
};

// A parameter of a unit (`unit`: "noise", "material") outside its field's range: throws
// std::invalid_argument "<unit>: <name> <value> is outside <lo>..<hi>".
inline void check_range(const std::string& unit, const std::string& name, int64_t value, int64_t lo,
                        int64_t hi) {
  if (value < lo || value > hi) {
    throw std::invalid_argument(unit + ": " + name + " " + std::to_string(value) + " is outside " +
                                std::to_string(lo) + ".." + std::to_string(hi));
  }
}

}  // namespace tmu
