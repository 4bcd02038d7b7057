// Transactions as the harness sees them: a fixed array of field values, each a port's raw
// bits, described by a Schema (names, widths, signedness, fraction bits) so that every block
// is printed, compared, saved and replayed by the same code.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fixed/fixed.hpp"

namespace tmu::tb {

inline constexpr int kMaxFields = 12;

struct Txn {
  std::array<uint64_t, kMaxFields> f{};
  friend bool operator==(const Txn&, const Txn&) = default;
};

struct Field {
  std::string name;
  fx::Format format;  // width, signedness and binary point of the port
};

class Schema {
 public:
  explicit Schema(std::vector<Field> fields);

  const std::vector<Field>& fields() const { return fields_; }
  size_t size() const { return fields_.size(); }
  int index(const std::string& name) const;  // -1 when absent

  // "name=value" for every field; signed and fractional fields also show their real value.
  std::string describe(const Txn& t) const;
  // One field's value for a report: hex bits, and the real value when it is not an integer.
  std::string value_text(int field, uint64_t bits) const;
  // Masks every field to its width (values read from files or generators).
  Txn masked(Txn t) const;

 private:
  std::vector<Field> fields_;
};

}  // namespace tmu::tb
