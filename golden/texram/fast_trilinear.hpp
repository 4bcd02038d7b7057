// A fast path of the golden trilinear unit (trilinear.hpp) for the callers that only want the
// colours: accuracy sweeps, renders, benchmarks. It returns the same RGBA8888 as
// texram::sample for every request, bit for bit (tests/texram_fast_test.cpp checks it on every
// border mode, texel configuration, filter, width and lambda range); it does not produce the
// memory plan (SamplePlan: taps, bank addresses, planes) that the co-simulation compares, so
// page timing and access records still come from the scalar golden.
//
// What makes it fast, measured in docs/performance.md:
// - The texture is prepared once: each level's texels converted to RGBA8888 (luminance, CLUT
//   look-up, single component, CCC decode) in a plain row-major array, instead of eight bank
//   reads and a conversion per tap. The array has a one-texel margin holding the border
//   colour, so border mode is a clamp to [-1, n] and an outside tap reads the margin.
// - The blend is exact integer arithmetic in SWAR lanes of a 64-bit word: a row's two taps
//   in four 16-bit lanes (each <= 255 * 2^W), then rows and the level weight in two words of
//   two 32-bit lanes (each <= 255 * 2^3W < 2^32), rounded once as the golden rounds.
// - Per-level shifts and sizes are precomputed; no range checks, no std::optional, no throws
//   on the sample path (the configuration is checked once, in the constructor).
//
// The prepared texture assumes that the replica cells of levels narrower than two grid cells
// hold the same bytes as the cells they replicate, as every constructor of TexramTexture
// writes them (the golden reads the replica by the tap's parity); the constructor checks it and
// throws std::invalid_argument if not.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "texram/layout.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram {

// The levels one lambda selects and their weights (choose_levels, reduced to what the blend
// needs). Shared by every probe of a footprint.
struct FastLevels {
  int count = 1;                 // levels read: 1 or 2
  std::array<int, 2> level{};    // the levels
  std::array<uint32_t, 2> lw{};  // level weights (2^W - wl, wl); 1 for bilinear
  int drop = 0;                  // bits the blend drops: 3W trilinear, 2W bilinear
};

class FastTrilinear {
 public:
  // Prepares `texture` for sampling with `config` (the texels' conversion depends on
  // config.single_channel, the margin on config.border_rgba). Throws std::invalid_argument
  // on widths outside 1..8 or replica cells that differ.
  FastTrilinear(const TexramTexture& texture, const SamplerConfig& config);
  FastTrilinear(const FastTrilinear&) = delete;  // levels_ point into texels_
  FastTrilinear& operator=(const FastTrilinear&) = delete;
  FastTrilinear(FastTrilinear&&) = default;  // the vector's buffer moves with it
  FastTrilinear& operator=(FastTrilinear&&) = default;

  // texram::sample(texture, config, request), without the plan.
  uint32_t sample(const Request& request) const {
    return sample_at(levels(request.lambda), request);
  }
  // Every request in order; out.size() must be requests.size().
  void sample_batch(std::span<const Request> requests, std::span<uint32_t> out) const;

  // The two halves of sample(), for callers that sample many points at one lambda.
  FastLevels levels(int32_t lambda) const;
  uint32_t sample_at(const FastLevels& levels, const Request& request) const;

  const SamplerConfig& config() const { return config_; }

 private:
  // A prepared level: texel (x, y) at origin[y * stride + x], x in -1..w, y in -1..h.
  struct Level {
    const uint32_t* origin = nullptr;
    int64_t stride = 0;
    int64_t w = 0, h = 0;
    int coord_drop = 0;  // port fraction bits above S at this level: 8 - S + level
  };

  uint32_t bilinear(const FastLevels& levels, int32_t u, int32_t v) const;
  uint32_t nearest(int level, int32_t u, int32_t v) const;
  uint32_t combine_fast(uint32_t t, uint32_t shade) const;

  SamplerConfig config_;
  Geometry geometry_;  // the sizes sphere addressing scales to
  int top_ = 0;
  std::vector<uint32_t> texels_;
  std::array<Level, kMaxLevels> level_{};
};

}  // namespace tmu::texram
