// Golden model of footprint assembly (000 §10, eq. 19-22, Figs. 12-13): a pixel's elongated
// footprint in the texture, the parallelogram spanned by r1 = d(u,v)/dx and r2 = d(u,v)/dy,
// approximated by N square trilinear probes marched along its longer side. This file is the
// specification the hls and rtl models match.
//
// Setup (the "marcher"), with Widths {D deriv bits, T table bits, F log fraction bits}:
// - Block-floating derivatives: sh = max(0, bitlen(max |component|) - D); each component
//   becomes sign * (|c| >> sh), so the products below are D x D bits. The shift cancels in
//   every ratio; it is added back to the logarithms.
// - Squared lengths s1 = |r1|^2, s2 = |r2|^2 and the area a = |r1 x r2| (twice the area of
//   the triangle r1, r2), exact on the shifted components. The longer side is r1 when
//   s1 >= s2, else r2; smax, smin the larger and smaller square.
// - lg(x) for x > 0: e = index of the leading one, i = the bits below it rounded half up to T
//   bits (zero-padded when fewer; i = 2^T when the rounding carries), lg = e * 2^F + LOG[i]
//   with LOG[i] = 2^F log2(1 + i / 2^T), i = 0 .. 2^T (2^T + 1 entries; LOG[2^T] = 2^F). The
//   error is centred (at most half a table step) and exact powers of two are exact. LOG is
//   F + 1 digits of the digit recurrence in Q1.30 rounded half up (log2_table_entry: integer
//   arithmetic the RTL repeats at elaboration; it equals the correctly rounded value for
//   every T and F allowed, a test checks). lg(0) is "zero" (minus infinity).
// - In G = F + 1 fraction bits (half a log step is exact), with raw values in units of
//   2^-16 per square and 2^-16 for the area (the ports have 8 fraction bits):
//     log2 |r_max|        = lg(smax) + 2 sh 2^F - 16 2^F
//     heights  log2 q     = 2 lg(a) - lg(smax) + 2 sh 2^F - 16 2^F   (q = a / |r_max|)
//              rho        = 2 (lg(smax) - lg(a))                     (rho = log2 |r_max| / q)
//     sides    log2 q     = lg(smin) + 2 sh 2^F - 16 2^F             (q = |r_min|)
//              rho        = lg(smax) - lg(smin)
//   "heights" is the reading of eq. 19 with d1, d2 the parallelogram's heights
//   |r1 x r2| / |r1| and |r1 x r2| / |r2|: then min(|r1|, |r2|, d1, d2) = a / |r_max|.
// - k = log2 N = round(rho) (half up: geometric rounding, ratio >= 2^(j + 1/2) gives N >= 2^(j+1)),
//   clamped to 0..log2_max_probes; a = 0 (a line footprint, or one vector zero) gives the
//   maximum. Probes are at least a quarter texel apart: k <= max(0, floor(log2 |r_max|) + 2),
//   exact from the leading one of smax. Closer probes add cost and almost nothing else
//   (docs/footprint.md measures it); a footprint under half a texel (magnification) gets one
//   probe, and the cost grows smoothly with the footprint's length. Both vectors zero: k = 0.
// - lambda = max(log2 q, log2 |r_max| - k) in G bits (when N is clamped, or rounded down, the
//   probes grow so that N of them still cover the footprint's length), rounded half up to
//   SQ6.8 and saturated; both vectors zero (or a = 0 with the max clamp unable to cover:
//   never) gives the smallest lambda.
// Probes: n = -(N - 1), -(N - 3), ..., N - 1 (N probes, in that order), at
//   p_n = p + n r / (2N), computed exactly and rounded half up to the port's 8 fraction bits:
//   (p 2^(k+1) + n r + 2^k) >> (k + 1). A coordinate beyond the port's range wraps modulo
//   2^16 texels on a wrap or mirror axis (a multiple of every period: the sample is the same)
//   and saturates on a clamp or border axis (beyond the edge either way: the same sample).
// Each probe is a trilinear-unit sample (texram::sample) at lambda with the fragment's shade
// (the unit's eq. 5 applies per probe); the result is the per-channel average of the N
// colours, (sum + N/2) >> k. The sums need 8 + 4 bits for 16 probes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "footprint/q_rule.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::footprint {

// The edge length q of eq. 19.
// The setup's internal precision.
struct Widths {
  // D: significant bits of the derivative components, 6..24. The shorter vector vanishes only
  // at ratios beyond 2^(D-1) >= 32, where N is at its maximum of 16 anyway.
  int deriv_bits = 12;
  int table_bits = 7;  // T: mantissa bits indexing the log2 table, 1..10
  int log_frac = 8;    // F: fraction bits of a logarithm, 1..12
  friend bool operator==(const Widths&, const Widths&) = default;
};

struct Config {
  int log2_max_probes = 3;  // 0..4: at most 2^this probes (the 3-bit port: 5..7 act as 4)
  QRule q_rule = QRule::kHeights;
  Widths widths;
};

// One fragment: raw port values.
struct Request {
  int32_t u = 0, v = 0;      // TexCoord SQ16.8
  int32_t r1u = 0, r1v = 0;  // TexDeriv SQ16.8: d(u, v)/dx
  int32_t r2u = 0, r2v = 0;  // TexDeriv SQ16.8: d(u, v)/dy
  uint32_t shade = 0;        // I_d, RGBA8888
};

// lg(x) of the setup: zero, or e 2^F + LOG[i].
struct Log2 {
  bool zero = true;
  int64_t value = 0;  // F fraction bits
};
Log2 log2_fixed(uint64_t x, const Widths& widths);
// LOG[i], i = 0 .. 2^T, the table's entries (F fraction bits).
uint32_t log2_table_entry(uint32_t index, const Widths& widths);

// The setup's first step: r1 and r2 scaled down together to deriv_bits (truncated toward
// zero) by `shift` bits, their squared lengths and the area |r1 x r2| of the parallelogram.
struct Extents {
  uint64_t s1 = 0, s2 = 0, area = 0;
  int shift = 0;
};
Extents extents(const Request& request, const Widths& widths);

// The setup's result: what the marcher sends down with each probe.
struct Plan {
  int log2_n = 0;          // k: N = 2^k probes
  bool r2_longer = false;  // the marching direction is r2 (else r1)
  int32_t lambda = 0;      // Lod SQ6.8 of every probe
};
Plan plan(const Request& request, const Config& config);

// Probe i (0 .. N-1) of a fragment: its position (wrapped or saturated per axis as the
// sampler's border modes say), lambda and shade.
texram::Request probe(const Request& request, const Plan& plan, int i,
                      const texram::SamplerConfig& sampler);

// The per-channel average of 2^log2_n colours, rounded half up.
uint32_t average(std::span<const uint32_t> colours, int log2_n);

// The whole unit: plan, probes through the trilinear unit, average. `probe_plans` (optional)
// receives every probe's memory plan, in order.
uint32_t sample(const texram::TexramTexture& texture, const texram::SamplerConfig& sampler,
                const Config& config, const Request& request,
                std::vector<texram::SamplePlan>* probe_plans = nullptr);

std::string_view name(QRule rule);
std::optional<QRule> parse_q_rule(std::string_view text);

}  // namespace tmu::footprint
