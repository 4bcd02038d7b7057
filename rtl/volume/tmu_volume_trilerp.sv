/// The trilinear interpolator of the volume unit (000 §13: the eight neighbouring voxels
/// "tri-linearly interpolated"; Fig. 15: the gradient components "fed through the trilinear
/// interpolator"): the exact sum of eight 10-bit unsigned samples c[x + 2 y + 4 z] weighted by
/// the pairs (256 - w, w) per axis, as seven nested lerps of the TEXRAM's lerp datapath
/// (tmu_trilinear_lerp; golden fx::trilerp's exact weighted sum, before its one rounding).
/// Combinational; the sum has 24 fraction bits.
///
/// Example: all samples 100, any weights: sum = 100 2^24.
module tmu_volume_trilerp (
  input  logic [8*10-1:0] c_i,
  input  logic [7:0]      wx_i,
  input  logic [7:0]      wy_i,
  input  logic [7:0]      wz_i,
  output logic [33:0]     sum_o
);

  logic [4*18-1:0] xs;  // along x: c[2i], c[2i+1]
  logic [2*26-1:0] ys;  // along y
  for (genvar i = 0; i < 4; i++) begin : gen_x
    tmu_trilinear_lerp #(.AW(10), .FW(8)) u_lerp (
      .a_i (c_i[(2*i)*10 +: 10]),
      .b_i (c_i[(2*i+1)*10 +: 10]),
      .f_i (wx_i),
      .c_o (xs[i*18 +: 18])
    );
  end
  for (genvar i = 0; i < 2; i++) begin : gen_y
    tmu_trilinear_lerp #(.AW(18), .FW(8)) u_lerp (
      .a_i (xs[(2*i)*18 +: 18]),
      .b_i (xs[(2*i+1)*18 +: 18]),
      .f_i (wy_i),
      .c_o (ys[i*26 +: 26])
    );
  end
  tmu_trilinear_lerp #(.AW(26), .FW(8)) u_lerp_z (
    .a_i (ys[0 +: 26]),
    .b_i (ys[26 +: 26]),
    .f_i (wz_i),
    .c_o (sum_o)
  );

endmodule
