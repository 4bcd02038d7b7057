// Fuzz target: the .ccc container reader (golden/ccc/ccc_texture.hpp, ccc::parse, which
// read_ccc calls with the file's bytes). Every byte of the container is meaningful, so a file
// that parses must serialize back to exactly the same bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "ccc/ccc_texture.hpp"
#include "common/error.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::string name = "fuzz.ccc";
  try {
    const tmu::ccc::Texture tex = tmu::ccc::parse(bytes, name);
    TMU_FUZZ_CHECK(tex.width >= 1 && tex.height >= 1);
    TMU_FUZZ_CHECK(tmu::ccc::serialize(tex) == bytes);
  } catch (const tmu::InputError& e) {
    TMU_FUZZ_CHECK(tmu::fuzz::names_file_and_reason(e, name));
    TMU_FUZZ_CHECK(!e.field().empty());  // parse always names the field (magic, width, ...)
  }
  return 0;
}
