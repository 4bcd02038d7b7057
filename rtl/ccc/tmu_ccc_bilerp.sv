/// Bilinear blend of one 8-bit channel: the project's one blend rule (golden/fixed/blend.hpp,
/// fx::bilerp_u8). Combinational.
///
/// The weights of a pair are (256 - f, f); products are exact and the UQ8.16 sum is rounded
/// once, half up:
///   top = c00 (256 - fx) + c10 fx,  bot = c01 (256 - fx) + c11 fx        (UQ8.8)
///   out = (top (256 - fy) + bot fy + 2^15) >> 16
/// Each pair is computed as a lerp, a (256 - f) + b f = 256 a + (b - a) f, one multiplier per
/// lerp. The difference b - a is negative at times; the arithmetic wraps at the full width
/// (two's complement), and because the exact result is known to lie in 0..2^W-1 the wrapped
/// value is the exact one.
///
/// Example: c00 = 10, c10 = 20, c01 = 30, c11 = 40, fx = 0x80, fy = 0x40:
///   top = 15.0, bot = 35.0, out = round(15 + 20 * 0.25) = 20.
module tmu_ccc_bilerp (
  /// Texels at (x0, y0), (x1, y0), (x0, y1), (x1, y1).
  input  tmu_pkg::channel_t       c00_i,
  input  tmu_pkg::channel_t       c10_i,
  input  tmu_pkg::channel_t       c01_i,
  input  tmu_pkg::channel_t       c11_i,
  /// Weights of x1 and y1, UQ0.8.
  input  tmu_pkg::filter_weight_t fx_i,
  input  tmu_pkg::filter_weight_t fy_i,
  /// Blended channel.
  output tmu_pkg::channel_t       c_o
);

  localparam int unsigned CW = tmu_pkg::ChannelW;       // 8
  localparam int unsigned WW = tmu_pkg::FilterWeightW;  // 8
  localparam int unsigned HW = CW + WW;                 // UQ8.8 row value: 0..65280
  localparam int unsigned VW = CW + 2 * WW;             // UQ8.16 sum, rounded: below 2^24
  // Half an LSB of the result, added before dropping the 16 fraction bits.
  localparam logic [VW-1:0] RoundHalf = VW'(1) << (2 * WW - 1);

  logic [HW-1:0] top, bot;
  logic [VW-1:0] top_v, bot_v, sum;

  assign top = {c00_i, WW'(0)} + (HW'(c10_i) - HW'(c00_i)) * HW'(fx_i);
  assign bot = {c01_i, WW'(0)} + (HW'(c11_i) - HW'(c01_i)) * HW'(fx_i);

  assign top_v = VW'(top);
  assign bot_v = VW'(bot);
  assign sum   = {top, WW'(0)} + (bot_v - top_v) * VW'(fy_i) + RoundHalf;
  assign c_o   = sum[VW-1:2*WW];

  logic unused_bits;
  assign unused_bits = ^sum[2*WW-1:0];

endmodule
