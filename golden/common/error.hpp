// Errors a user can cause (a bad file, field or argument). The message always names the
// file, the field and the reason, so the CLI can print it as-is and exit non-zero.
#pragma once

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

}  // namespace tmu
