// Fuzz target: the fragment-trace reader (host/trace/fragment_trace.hpp, read_trace from a
// stream, which read_trace(path) calls with the open file). A trace it accepts has a frame of
// 1..kMaxTexSize a side and every fragment inside it.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "common/error.hpp"
#include "formats/formats.hpp"
#include "fuzz_check.hpp"
#include "trace/fragment_trace.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const std::string name = "fuzz.trace.csv";
  try {
    const tmu::host::FragmentTrace t = tmu::host::read_trace(in, name);
    TMU_FUZZ_CHECK(t.width >= 1 && t.width <= tmu::formats::kMaxTexSize);
    TMU_FUZZ_CHECK(t.height >= 1 && t.height <= tmu::formats::kMaxTexSize);
    for (const tmu::host::FragmentRecord& r : t.records) {
      TMU_FUZZ_CHECK(r.x < t.width && r.y < t.height);
    }
  } catch (const tmu::InputError& e) {
    TMU_FUZZ_CHECK(tmu::fuzz::names_file_and_reason(e, name));
  }
  return 0;
}
