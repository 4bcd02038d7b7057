// The noise unit as a co-simulation block, `texsim cosim noise` (alias perlin): (u, v, w)
// SolidCoord SQ12.12 -> p (NoiseValue SQ0.11) = golden noise(NoiseConfig{}, u, v, w), at the
// golden default widths (F = S = B = 8, X = 4), the ports' formats (002 §4.1;
// golden/perlin/noise.hpp, rtl/perlin/tmu_noise.sv, hls/perlin/noise_sc.hpp).
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/noise/noise_ports.hpp"
#include "blocks/registry.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(noise)

namespace tmu::tb {

// The golden noise's intermediate values at the default widths, for coverage and tests:
// per axis the lattice index (mod 2^12), the raw 12-bit fraction, the fade index and weight;
// the eight corners' lattice values (index du + 2 dv + 4 dw), the lerps' results, and
// whether a lerp rounded a tie (c (b - a) = 2^(B-1) mod 2^B) or stepped down (b < a).
struct NoiseTrace {
  std::array<uint32_t, 3> index{}, frac{}, fade_index{}, fade{};
  std::array<int32_t, 8> corner{};
  std::array<int32_t, 4> x{};
  std::array<int32_t, 2> y{};
  int32_t p = 0;
  bool tie = false;
  bool step_down = false;
};
NoiseTrace trace_noise(int64_t u, int64_t v, int64_t w);

class NoiseBlock : public DescribedBlockOf<NoiseBlock> {
 public:
  explicit NoiseBlock(const BlockOptions& options = {});
  TMU_BLOCK_PIECES;
  std::unique_ptr<Model> ideal() const override;

 private:
  // cover() sees every item in order; the fade indices seen so far per axis.
  mutable size_t cover_next_ = 0;
  mutable std::array<std::bitset<256>, 3> seen_fade_;
};

}  // namespace tmu::tb
