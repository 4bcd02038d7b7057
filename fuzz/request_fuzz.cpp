// Fuzz target: the sample request-file reader (tb/texsim/request_file.hpp, read_requests from a
// stream, which read_requests(path) calls with the open file). Every request it accepts is
// finite and within the ports' ranges (u, v in SQ16.8, lambda in SQ6.8).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "formats/formats.hpp"
#include "fuzz_check.hpp"
#include "texsim/request_file.hpp"

namespace {

double port_limit(const tmu::fx::Format& f) {
  return std::ldexp(static_cast<double>(f.max_raw()), -f.frac_bits);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const std::string name = "fuzz.requests.csv";
  try {
    const std::vector<tmu::texsim::SampleRequest> requests = tmu::texsim::read_requests(in, name);
    TMU_FUZZ_CHECK(!requests.empty());
    const double uv = port_limit(tmu::formats::kTexCoord), lod = port_limit(tmu::formats::kLod);
    for (const tmu::texsim::SampleRequest& r : requests) {
      TMU_FUZZ_CHECK(std::abs(r.u) <= uv && std::abs(r.v) <= uv && std::abs(r.lambda) <= lod);
      if (r.derivatives) {
        for (double d : *r.derivatives) TMU_FUZZ_CHECK(std::isfinite(d));
      }
    }
  } catch (const tmu::InputError& e) {
    TMU_FUZZ_CHECK(tmu::fuzz::names_file_and_reason(e, name));
  }
  return 0;
}
