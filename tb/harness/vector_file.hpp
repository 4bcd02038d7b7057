// Vector files: stimulus as CSV, one input item per line, a header naming the schema's
// fields in any order. Values are decimal (may be negative for signed fields) or 0x-hex
// bits; '#' starts a comment. A missing field is 0.
#pragma once

#include <string>
#include <vector>

#include "harness/txn.hpp"

namespace tmu::tb {

// Throws InputError naming the file, line and field on a malformed file.
std::vector<Txn> read_vectors(const std::string& path, const Schema& schema);
// Atomic; hex bits in the schema's field order.
void write_vectors(const std::string& path, const Schema& schema, const std::vector<Txn>& items);

}  // namespace tmu::tb
