// What every fuzz target shares: the check of a reader's promise on an input it accepted or
// rejected. A broken promise prints what was expected and aborts, which libFuzzer reports as a
// crash (and the replay test as a failure), like a sanitizer report would.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/error.hpp"

namespace tmu::fuzz {

[[noreturn]] inline void broken_promise(const char* what, const char* file, int line) {
  std::fprintf(stderr, "fuzz check failed at %s:%d: %s\n", file, line, what);
  std::abort();
}

// An InputError must name the file it was given and a reason (the field may be empty when
// the problem is the whole file: "no requests").
inline bool names_file_and_reason(const InputError& e, const std::string& name) {
  return e.file() == name && !e.reason().empty();
}

}  // namespace tmu::fuzz

#define TMU_FUZZ_CHECK(cond) \
  ((cond) ? (void)0 : ::tmu::fuzz::broken_promise(#cond, __FILE__, __LINE__))
