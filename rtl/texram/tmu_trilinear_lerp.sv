/// One exact linear interpolation of the trilinear blend: c = a (2^FW - f) + b f, computed
/// as a 2^FW + (b - a) f with one multiplier and no rounding (the nested lerps of the blend
/// are the golden model's exact weighted sum; the unit rounds once, at the end).
/// Combinational.
///
/// The difference b - a is signed; the product is exact; the sum is taken modulo 2^(AW+FW),
/// which is exact because the result lies in 0 .. (2^AW - 1) 2^FW.
///
/// Example: AW = 8, FW = 8, a = 10, b = 20, f = 0x40: c = 2560 + 10 * 64 = 3200 (12.5 * 256).
module tmu_trilinear_lerp #(
  /// Bits of the two values (unsigned).
  parameter int unsigned AW = 8,
  /// Bits of the weight: f / 2^FW.
  parameter int unsigned FW = 8
) (
  input  logic [AW-1:0]    a_i,
  input  logic [AW-1:0]    b_i,
  input  logic [FW-1:0]    f_i,
  /// a (2^FW - f) + b f, exact: FW more bits than the values.
  output logic [AW+FW-1:0] c_o
);

  localparam int unsigned OW = AW + FW;
  localparam int unsigned PW = AW + FW + 2;  // signed (AW+1) x signed (FW+1)

  if (AW < 1 || FW < 1) begin : gen_check
    $error("tmu_trilinear_lerp: AW and FW must be at least 1");
  end

  logic signed [AW:0]   diff;
  logic signed [FW:0]   weight;
  logic signed [PW-1:0] product;

  assign diff    = $signed({1'b0, b_i}) - $signed({1'b0, a_i});
  assign weight  = $signed({1'b0, f_i});
  assign product = PW'(diff) * PW'(weight);
  assign c_o     = {a_i, FW'(0)} + product[OW-1:0];

  logic unused_bits;
  assign unused_bits = ^product[PW-1:OW];

endmodule
