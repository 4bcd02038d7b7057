// A fast path of golden footprint assembly (footprint.hpp) for the callers that only want the
// colours. It returns the same RGBA8888 as footprint::sample for every request, bit for bit
// (tests/footprint_fast_test.cpp checks it over every probe maximum, both q rules, setup widths,
// border modes and texel configurations); it does not produce the probes' memory plans
// (`probe_plans`) that the co-simulation compares.
//
// What makes it fast, besides the fast trilinear unit (texram/fast_trilinear.hpp):
// - The log2 table is built once (the golden evaluates an entry's digit recurrence per call).
// - The level choice of the fragment's lambda is made once for all its probes.
// - Probe positions step by 2 r from the first, and the average is summed in 16-bit lanes.
// - The probes go to the trilinear unit's loop in one call per fragment.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "footprint/footprint.hpp"
#include "formats/formats.hpp"
#include "texram/fast_trilinear.hpp"

namespace tmu::footprint {

class FastFootprint {
 public:
  // Throws std::invalid_argument where footprint::plan and FastTrilinear would.
  FastFootprint(const texram::TexramTexture& texture, const texram::SamplerConfig& sampler,
                const Config& config);

  // footprint::plan(request, config).
  Plan plan(const Request& request) const;
  // footprint::sample(texture, sampler, config, request), without the probe plans.
  uint32_t sample(const Request& request) const;
  // Every request in order; out.size() must be requests.size().
  void sample_batch(std::span<const Request> requests, std::span<uint32_t> out) const;

 private:
  static constexpr size_t kMaxProbes = size_t{1} << formats::kMaxProbeLog2;
  int64_t lg(uint64_t x) const;  // log2_fixed's value for x > 0

  texram::FastTrilinear unit_;
  Config config_;
  std::vector<int64_t> log_table_;  // LOG[i], i = 0 .. 2^T
};

}  // namespace tmu::footprint
