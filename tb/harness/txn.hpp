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

// The most fields of any channel of any block (the op field included): the clip-map unit's
// memory request (eight enables, eight addresses, we and eight bytes).
inline constexpr int kMaxFields = 32;

struct Txn {
  std::array<uint64_t, kMaxFields> f{};
  friend bool operator==(const Txn&, const Txn&) = default;
};

struct Field {
  std::string name;
  fx::Format format;  // width, signedness and binary point of the port
  int slot = -1;      // the Txn field it lives in; -1: its index in the schema
  int op = -1;        // input items: the op (channel) it belongs to; -1: every item's
};

// The fields of a channel, or of the input items of a block whose stimulus channels share the
// slots: then field 0 is `op`, the channel of the item, and a field belongs to one op.
class Schema {
 public:
  explicit Schema(std::vector<Field> fields);

  const std::vector<Field>& fields() const { return fields_; }
  size_t size() const { return fields_.size(); }
  int index(const std::string& name) const;  // -1 when absent
  const Field& field(size_t index) const { return fields_[index]; }
  // Whether field `index` is one of item t's fields (always, for a schema without op).
  bool carries(size_t index, const Txn& t) const;

  // "name=value" for every field of t; signed and fractional fields also show their real value.
  std::string describe(const Txn& t) const;
  // One field's value for a report: hex bits, and the real value when it is not an integer.
  std::string value_text(int field, uint64_t bits) const;
  // Masks every field to its width and clears the slots t's op does not use (values read from
  // files or generators).
  Txn masked(Txn t) const;

 private:
  std::vector<Field> fields_;
  bool has_op_ = false;
};

}  // namespace tmu::tb
