/// One axis of a resample location (golden volume::axis_corners, golden/volume/unit.hpp): the
/// position clamped to the volume (0 .. n - 1: a location outside takes the nearest face's),
/// the lower corner i0 = floor(p) and the weight of the upper corner, the top W bits of p's
/// 16 fraction bits (truncated, as golden), carried as an 8-bit weight with the bits below W
/// zero; and what the access sequencer and the gradient need to know about the corners:
///   same    i1 = i0 (p = n - 1: the far corner clamped onto the near one, weight 0)
///   first   i0 = 0 (the neighbour i0 - 1 is outside)
///   inner2  i0 + 2 < n (the neighbour i0 + 2 is inside)
/// Combinational.
///
/// Why an 8-bit weight serves every W: with w8 = w 2^(8-W), the pair (256 - w8, w8) is 2^(8-W)
/// times golden's (2^W - w, w), so each blend's exact sum is 2^(3(8-W)) times golden's and
/// rounding it by 3 (8 - W) more bits gives golden's result bit for bit.
///
/// Example: n = 5, p = 3.75 (raw 0x3C000), W = 2: i0 = 3, w8 = 0xC0 (0.75), same 0, first 0,
/// inner2 0 (3 + 2 = 5 is outside).
module tmu_volume_axis (
  input  tmu_pkg::voxel_pos_t     pos_i,
  input  tmu_pkg::volume_size_t   n_i,
  /// The weight bits kept: the top W of 8 (W = 8: all).
  input  logic [7:0]              weight_mask_i,
  output logic [8:0]              i0_o,
  output logic [7:0]              w_o,
  output logic                    same_o,
  output logic                    first_o,
  output logic                    inner2_o
);

  localparam int unsigned PW   = tmu_pkg::VoxelPosW;     // 26
  localparam int unsigned Frac = tmu_pkg::VoxelPosFrac;  // 16
  localparam int unsigned NW   = tmu_pkg::VolumeSizeW;   // 10

  if (Frac != 16 || PW != 26 || NW != 10) begin : gen_check
    $error("tmu_volume_axis: built for VoxelPos SQ10.16 and 10-bit sizes");
  end

  // (n - 1) 2^16, the largest position, and the clamped position (n <= 512 for a valid size:
  // it fits 25 bits; a wider n only makes a wrong volume's positions wrong).
  logic signed [PW:0] top, p, clamped;
  logic [NW-1:0]      last_index;
  assign last_index = n_i - NW'(1);
  assign top        = {1'b0, PW'(last_index) << Frac};
  assign p          = {pos_i[PW-1], pos_i};
  always_comb begin
    if (p < 0) clamped = '0;
    else if (p > top) clamped = top;
    else clamped = p;
  end

  assign i0_o     = clamped[Frac +: 9];
  assign w_o      = clamped[Frac-8 +: 8] & weight_mask_i;
  assign same_o   = NW'(i0_o) == last_index;
  assign first_o  = i0_o == '0;
  assign inner2_o = NW'(i0_o) + NW'(2) < n_i;

  logic unused_bits;
  assign unused_bits = ^{clamped[PW:Frac+9], clamped[Frac-9:0]};

endmodule
