// Sample request files (`texsim sample --requests R.csv`) and sample result files.
//
// Requests: CSV, one request per line, '#' starts a comment. An optional header names the
// columns in any order; without one the columns are u,v,lambda. Columns:
//   u, v      texel coordinates of level 0, texel centres at i + 0.5 (reals)
//   lambda    level of detail (real; < 0 magnifies, beyond the last level clamps)
//   shade     optional I_d of eq. 5, 0xRRGGBBAA (default 0xFFFFFFFF)
//   dudx, dvdx, dudy, dvdy   optional derivative vectors (read and kept for later blocks)
// Values outside the ports' ranges (u, v in SQ16.8, lambda in SQ6.8) are errors, not
// silently saturated.
//
// Results: CSV with the header r,g,b,a and one line per request, integers 0..255.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace tmu::texsim {

struct SampleRequest {
  double u = 0, v = 0, lambda = 0;
  uint32_t shade = 0xFFFFFFFFu;
  std::optional<std::array<double, 4>> derivatives;  // dudx, dvdx, dudy, dvdy
};

// Throws InputError naming the file, the line and the column.
std::vector<SampleRequest> read_requests(const std::string& path);
// The same from a stream (tests, fuzzing); `name` stands for the file in messages.
std::vector<SampleRequest> read_requests(std::istream& in, const std::string& name);

// Writes the results atomically (RGBA8888 values).
void write_results(const std::string& path, const std::vector<uint32_t>& rgba);

}  // namespace tmu::texsim
