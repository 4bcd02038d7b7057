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
// - The blend is exact integer arithmetic in SWAR lanes of a 64-bit word (rgba_lanes.hpp): a
//   row's two taps in four 16-bit lanes (each <= 255 * 2^W), then rows and the level weight in
//   two words of two 32-bit lanes (each <= 255 * 2^3W < 2^32), rounded once as the golden
//   rounds. The arrays hold each texel already spread to 16-bit lanes (8 bytes a texel: the
//   256 x 256 pyramid is 0.7 MB and still fits the L2 cache here).
// - Per-level shifts and sizes are precomputed; no range checks, no std::optional, no throws
//   on the sample path (the configuration is checked once, in the constructor).
// - The sample loop is compiled once per border mode pair, for nearest or bi/trilinear, and
//   for the default widths (all 8: constant shifts) or any: the constructor picks the loop,
//   and a batch pays one indirect call. The work per sample is arithmetic (requests confined
//   to a few texels, always in L1, run no faster): branches on the configuration and variable
//   shifts cost a third of it.
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
  FastTrilinear(const FastTrilinear&) = delete;  // level_ points into texels_
  FastTrilinear& operator=(const FastTrilinear&) = delete;
  FastTrilinear(FastTrilinear&&) = default;  // the vector's buffer moves with it
  FastTrilinear& operator=(FastTrilinear&&) = default;

  // texram::sample(texture, config, request), without the plan.
  uint32_t sample(const Request& request) const {
    uint32_t out = 0;
    batch_(*this, std::span(&request, 1), std::span(&out, 1));
    return out;
  }
  // Every request in order; out.size() must be requests.size().
  void sample_batch(std::span<const Request> requests, std::span<uint32_t> out) const;

  // The level choice of a lambda, and n points sampled at it with one shade (a footprint's
  // probes: port coordinates u[i], v[i]; out[i] = texram::sample of (u[i], v[i], lambda, shade)).
  FastLevels levels(int32_t lambda) const;
  void sample_points(const FastLevels& levels, const int32_t* u, const int32_t* v, int n,
                     uint32_t shade, uint32_t* out) const {
    points_(*this, levels, u, v, n, shade, out);
  }

  const SamplerConfig& config() const { return config_; }

 private:
  // A prepared level: texel (x, y) at origin[y * stride + x], x in -1..w, y in -1..h.
  struct Level {
    const uint64_t* origin = nullptr;  // texels in 16-bit lanes (rgba_lanes.hpp: spread16)
    int64_t stride = 0;
    int64_t w = 0, h = 0;
    int coord_drop = 0;  // port fraction bits above S at this level: 8 - S + level
  };
  struct Kernels;  // the sample loops, one per configuration class (fast_trilinear.cpp)
  using BatchFn = void (*)(const FastTrilinear&, std::span<const Request>, std::span<uint32_t>);
  using PointsFn = void (*)(const FastTrilinear&, const FastLevels&, const int32_t*, const int32_t*,
                            int, uint32_t, uint32_t*);

  SamplerConfig config_;
  Geometry geometry_;  // the sizes sphere addressing scales to
  int top_ = 0;
  std::vector<uint64_t> texels_;
  std::array<Level, kMaxLevels> level_{};
  BatchFn batch_ = nullptr;
  PointsFn points_ = nullptr;
};

}  // namespace tmu::texram
