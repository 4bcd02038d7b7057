/// One component of the reflection vector (001 §5, eq. 21; golden eval_coords in
/// golden/deflect/coord_eval.hpp): from a, b in SQ2.14,
///   r = 2 a b       (uR = 2 hN uN, vR = 2 hN vN)        MinusOne = 0
///   r = 2 a b - 1   (wR = 2 hN^2 - 1, with a = b = hN)  MinusOne = 1
/// The product is exact (28 fraction bits); doubling and rounding half up to 14 fraction bits
/// is (a b + 2^12) >> 13; then minus 2^14 for wR; saturated to SQ2.14 [-2, 2 - 2^-14].
///
/// Saturation is real: the tables' entries reach +-(1 - 2^-(W-1)), so |uN|, |vN|, |hN| reach
/// 32672 (1.994 for W = 10) and |2 hN uN| up to 7.95 (tables written with extreme values).
/// From a view frame's tables the normal is within a rounding error of unit length, so
/// |2 hN uN| <= hN^2 + uN^2 ~ 1 and nothing saturates. wR never saturates low: hN^2 >= 0
/// gives wR >= -1.
///
/// Example: a = b = hN = 16384 (1.0), MinusOne: (2^28 + 2^12) >> 13 = 32768, - 16384 =
/// 16384 (1.0).
module tmu_coord_reflect #(
  /// 1: subtract one (wR); 0: 2 a b (uR, vR).
  parameter bit MinusOne = 1'b0
) (
  input  tmu_pkg::unit_comp_t a_i,
  input  tmu_pkg::unit_comp_t b_i,
  output tmu_pkg::unit_comp_t r_o
);

  localparam int unsigned CW   = tmu_pkg::UnitCompW;       // 16
  localparam int unsigned Frac = tmu_pkg::UnitCompFrac;    // 14
  localparam int unsigned PW   = 2 * CW;                   // product, 28 fraction bits
  localparam int unsigned RW   = PW - (Frac - 1);          // after the shift by 13: 19 bits
  localparam logic signed [RW-1:0] Max = RW'((1 << (CW - 1)) - 1);
  localparam logic signed [RW-1:0] Min = -RW'(1 << (CW - 1));

  // |a b| <= 2^30, so the product, its rounding and the result minus one fit their widths.
  logic signed [PW-1:0] product;
  logic signed [RW-1:0] twice, value;

  assign product = PW'(a_i) * PW'(b_i);
  assign twice   = RW'((product + (PW'(1) << (Frac - 2))) >>> (Frac - 1));
  assign value   = MinusOne ? twice - (RW'(1) <<< Frac) : twice;
  assign r_o     = value > Max ? CW'(Max) : value < Min ? CW'(Min) : CW'(value);

endmodule
