// Reads a whole file into a string: the counterpart of write_file_atomically (atomic_file.hpp).
#pragma once

#include <fstream>
#include <iterator>
#include <string>

#include "common/error.hpp"

namespace tmu {

// The bytes of `path`; throws InputError naming the path when it cannot be opened or read.
inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open");
  // Not `out << in.rdbuf()`: that marks an empty file as a failure.
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(path, "", "cannot read");
  return bytes;
}

}  // namespace tmu
