#include "deflect/normal_encoder.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace tmu::deflect {

uint32_t seed_entry(uint32_t index, int seed_bits) {
  // round(2^15 / (1 + (i + 1/2) / 2^S)) = round(2^(16+S) / den) with den = 2^(S+1) + 2i + 1.
  const uint64_t den = (uint64_t{1} << (seed_bits + 1)) + 2 * uint64_t{index} + 1;
  return static_cast<uint32_t>(((uint64_t{1} << (17 + seed_bits)) + den) / (2 * den));
}

uint32_t divide_ratio(uint32_t num, uint32_t den, int seed_bits) {
  if (den == 0) return 0;
  const int s = std::countl_zero(den);
  const uint64_t d = (uint64_t{den} << s) >> 16;  // UQ1.15, [2^15, 2^16)
  const uint64_t n = (uint64_t{num} << s) >> 16;
  const uint32_t i = static_cast<uint32_t>(d >> (15 - seed_bits)) & ((1u << seed_bits) - 1);
  const uint64_t r0 = seed_entry(i, seed_bits);
  const uint64_t r1 = (r0 * ((uint64_t{1} << 31) - d * r0)) >> 29;  // UQ1.16
  return static_cast<uint32_t>(std::min<uint64_t>((n * r1) >> 15, uint64_t{1} << kRatioFrac));
}

uint32_t angle_index(const EncoderConfig& c, uint32_t t) {
  const uint32_t t16 = std::min<uint32_t>(t, (1u << kRatioFrac) - 1);
  const int clz16 = std::countl_zero(t16) - 16;
  const int e = std::min(clz16 / 2, c.lut_exp - 1);
  const uint32_t m = ((t16 << (2 * e)) & 0xFFFFu) >> (kRatioFrac - c.lut_mant);
  return (static_cast<uint32_t>(e) << c.lut_mant) | m;
}

uint32_t angle_entry(const EncoderConfig& c, uint32_t index) {
  const uint32_t e = index >> c.lut_mant;
  const uint32_t m = index & ((1u << c.lut_mant) - 1);
  const double scale = std::ldexp(1.0, -(c.lut_mant + 2 * static_cast<int>(e)));
  const double t_lo = m * scale, t_hi = (m + 1) * scale;
  const double step = (std::numbers::pi / 2.0) / c.grid.quarter();
  // rtl/deflect/tmu_normal_angle_lut.sv evaluates this same expression at elaboration.
  const double mid = (std::atan(std::sqrt(t_lo)) + std::atan(std::sqrt(t_hi))) / 2.0 / step;
  return static_cast<uint32_t>(std::floor(mid + 0.5));
}

std::vector<uint32_t> angle_table(const EncoderConfig& c) {
  std::vector<uint32_t> table(static_cast<size_t>(c.lut_entries()));
  for (size_t i = 0; i < table.size(); ++i) table[i] = angle_entry(c, static_cast<uint32_t>(i));
  return table;
}

NormalEncoder::NormalEncoder(const EncoderConfig& config)
    : config_(config), angle_(angle_table(config)) {}

SphereAngle NormalEncoder::encode(int16_t x, int16_t y, int16_t z, EncoderTrace* trace) const {
  const EncoderConfig& c = config_;
  EncoderTrace t;
  t.sx = x < 0;
  t.sy = y < 0;
  t.sz = z < 0;
  const auto magnitude = [](int16_t v) { return static_cast<uint32_t>(std::abs(int32_t{v})); };
  const uint32_t a = magnitude(x), b = magnitude(y), cz = magnitude(z);
  const uint32_t xx = a * a, yy = b * b, zz = cz * cz, hh = xx + zz;

  t.swap_phi = xx > zz;
  t.t_phi = divide_ratio(std::min(xx, zz), std::max(xx, zz), c.seed_bits);
  t.swap_theta = yy > hh;
  t.t_theta = divide_ratio(std::min(yy, hh), std::max(yy, hh), c.seed_bits);

  const uint32_t q = c.grid.quarter();
  const auto angle = [&](uint32_t ratio) { return ratio == 0 ? 0 : angle_[angle_index(c, ratio)]; };
  const uint32_t kp = angle(t.t_phi);
  const uint32_t kt = angle(t.t_theta);
  t.k_phi = t.swap_phi ? q - kp : kp;
  t.k_theta = t.swap_theta ? q - kt : kt;

  SphereAngle out;
  out.phi = expand_phi(c.grid, t.sx, t.sz, t.k_phi);
  out.theta = make_theta(c.grid, t.sy, std::min(t.k_theta, q - 1));
  if (trace) *trace = t;
  return out;
}

}  // namespace tmu::deflect
