// Golden model of the normal encoder (001 §4.1, eq. 12-16, Fig. 3): an interpolated,
// unnormalised Cartesian normal to (phi_N, theta_N) on the sphere grid without square roots
// or trigonometry. This file is the specification the hls and rtl models match.
//
// Input: N = (x, y, z), three UnitComp SQ2.14 components (any length, zero included).
// 1. Octant: the signs sx, sy, sz (a component < 0); a, b, c the magnitudes (16 bits).
// 2. Squares X = a^2, Y = b^2, Z = c^2 and H = X + Z (32 bits, exact).
// 3. Two ratios, the smaller over the larger so that both lie in [0, 1] (eq. 15-16):
//      phi:   t = min(X, Z) / max(X, Z) = tan^2 of the angle from the nearer of z, x
//      theta: t = min(Y, H) / max(Y, H) = tan^2 of the angle from the nearer of the
//             horizontal plane and the pole
//    "swap" records that the numerator was X > Z (resp. Y > H): the angle is then measured
//    from the other axis, Q - k. Equal squares do not swap (k = Q/2 either way).
// 4. Divider (t = num / den, 16 fraction bits, UQ1.16):
//    den = 0 (then num = 0 too) gives t = 0. Otherwise s = leading zeros of den (32 bits);
//    d = (den << s) >> 16 is the divisor in UQ1.15 (d in [2^15, 2^16)), n = (num << s) >> 16.
//    Seed: r0 = SEED[i], i the S bits of d below its leading one (S = seed_bits), SEED[i] =
//    round(2^15 / (1 + (i + 1/2) / 2^S)) (UQ1.15, integer arithmetic).
//    One Newton-Raphson step: r1 = (r0 (2^31 - d r0)) >> 29 (UQ1.16, truncated).
//    t = min((n r1) >> 15, 2^16). (r1 < 2^16 for every d at S >= 2, so equal squares give
//    65533 .. 65535 at S = 7 and the clamp is only a guard; they land in the top bucket.)
// 5. Angle table (the paper's 128-entry LUT): a floating index so that the table's steps
//    follow atan(sqrt(t)), whose slope is infinite at t = 0. With t16 = min(t, 2^16 - 1),
//    e = min(floor(clz16(t16) / 2), E - 1) (E = lut_exp exponent levels: an even shift keeps
//    sqrt exact), m = (t16 << 2e) >> (16 - M) (M = lut_mant bits), index = e 2^M + m; E 2^M
//    entries. Entry = round(((atan sqrt(t_lo) + atan sqrt(t_hi)) / 2) / delta) for the
//    bucket t_lo = m 2^-M 4^-e .. t_hi = (m + 1) 2^-M 4^-e: a step count 0 .. Q/2. E = 1
//    is the paper's linear index (M = 7: 128 entries); the default E = 4, M = 5 is 128
//    entries too, with a third of the linear table's worst error (docs/deflection.md).
//    Below the last exponent the mantissa's top two bits are never 00: 104 of those 128
//    entries are reachable (an index offset would use them, at one more subtractor).
// 6. k_phi = ANGLE[t_phi], except t_phi = 0 (a zero numerator, or one under 2^-16 of the
//    denominator: the normal lies in, or within 0.22 degrees of, a coordinate plane) gives 0
//    without the table, so the axes and the planes between them encode exactly (the first
//    bucket's midpoint is not 0). Q - k_phi when swapped;
//    phi_N = expand_phi(sx, sz, k_phi).
//    k_theta likewise (t_theta = 0 gives 0); theta_N = (sy, min(k_theta, Q - 1)).
// Stated expectations: the zero normal is (0, +0), +z; a pole (0, +-y, 0) is (0, +-(Q - 1));
// a normal on an octant boundary takes the non-negative side of its zero component; the
// encoding does not depend on the normal's length beyond the rounding of its components.
#pragma once

#include <cstdint>
#include <vector>

#include "deflect/sphere_grid.hpp"

namespace tmu::deflect {

struct EncoderConfig {
  SphereGrid grid;
  int seed_bits = 7;  // S: reciprocal seed table of 2^S entries, 2..12
  int lut_exp = 4;    // E: exponent levels of the angle table index, 1..8
  int lut_mant = 5;   // M: mantissa bits of the angle table index, 2..10
  int lut_entries() const { return lut_exp << lut_mant; }
  friend bool operator==(const EncoderConfig&, const EncoderConfig&) = default;
};

constexpr int kRatioFrac = 16;  // t in UQ1.16

// The encoder's intermediate values (tests and the block's coverage read them).
struct EncoderTrace {
  bool sx = false, sy = false, sz = false;
  bool swap_phi = false, swap_theta = false;
  uint32_t t_phi = 0, t_theta = 0;  // UQ1.16
  uint32_t k_phi = 0, k_theta = 0;  // steps after the swap, 0 .. Q
};

// The encoder with its angle table built once.
class NormalEncoder {
 public:
  explicit NormalEncoder(const EncoderConfig& config);
  const EncoderConfig& config() const { return config_; }
  SphereAngle encode(int16_t x, int16_t y, int16_t z, EncoderTrace* trace = nullptr) const;

 private:
  EncoderConfig config_;
  std::vector<uint32_t> angle_;
};

// The divider alone: num / den in UQ1.16 for num <= den.
uint32_t divide_ratio(uint32_t num, uint32_t den, int seed_bits);
uint32_t seed_entry(uint32_t index, int seed_bits);

// The angle table: its index for a ratio, and its entries.
uint32_t angle_index(const EncoderConfig& config, uint32_t t);
uint32_t angle_entry(const EncoderConfig& config, uint32_t index);
std::vector<uint32_t> angle_table(const EncoderConfig& config);

}  // namespace tmu::deflect
