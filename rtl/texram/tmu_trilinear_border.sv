/// The border operator of one tap coordinate (000 §6: OpenGL's wrap, clamp, border colour,
/// and mirroring) and the stored grid coordinate that serves it, exactly as texram::
/// plan_sample's resolve() and stored() (golden/texram/trilinear.cpp). Combinational.
///
/// An axis of level l of a 2^a texel side has n = 2^max(a - l, 0) texels. On the unresolved
/// tap coordinate t (two's complement):
///   wrap    t mod n (its low bits)
///   clamp   t clamped to 0..n-1
///   border  t; outside_o when t < 0 or t >= n (the tap takes the border colour)
///   mirror  mirrored repeat, period 2n: t mod 2n, reflected to 2n - 1 - (t mod 2n) when >= n
/// Stored coordinate (layout.hpp): the grid position, texels or (block grid) 4 x 4 CCC blocks
/// (coord / 4). A grid of one position is stored twice; the replica is the parity of the
/// unresolved grid position (t, or t / 4 for blocks), so neighbouring taps use two banks.
///
/// Example: n = 8 (a = 4, level 1), t = -3: wrap 5, clamp 0, border outside, mirror 2.
module tmu_trilinear_border #(
  /// Width of the tap coordinate (two's complement).
  parameter int unsigned TapW   = 18,
  /// Width of a level's texel coordinate: the TEXRAM's 1024 (MipCoord), or a clip-map's
  /// virtual 32k (ClipCoord, tmu_clip_hold and tmu_clipmap).
  parameter int unsigned CoordW = tmu_pkg::MipCoordW
) (
  input  logic [TapW-1:0]     tap_i,
  /// log2 of the level-0 side along this axis, and the level.
  input  tmu_pkg::mip_log2_t  log2_size_i,
  input  tmu_pkg::mip_level_t level_i,
  /// Border operator, decoded (none set: wrap).
  input  logic                clamp_i,
  input  logic                border_i,
  input  logic                mirror_i,
  /// The grid is 4 x 4 CCC blocks.
  input  logic                block_grid_i,
  /// Resolved texel coordinate (0 when outside), and whether the tap is outside (border).
  output logic [CoordW-1:0]   coord_o,
  output logic                outside_o,
  /// The stored grid coordinate holding the texel.
  output logic [CoordW-1:0]   stored_o
);

  localparam int unsigned Log2W  = tmu_pkg::MipLog2W;

  if (TapW <= CoordW || CoordW < tmu_pkg::MipCoordW) begin : gen_check
    $error("tmu_trilinear_border: TapW must exceed the coordinate width, which holds MipCoord");
  end

  logic [Log2W-1:0]  size_log2;  // log2 n
  logic [CoordW-1:0] mask;       // n - 1
  logic [TapW-1:0]   periods;    // floor(t / n), as bits (t >> log2 n)
  logic              negative, beyond, reflect, grid_one;
  logic [CoordW-1:0] low;

  assign size_log2 = log2_size_i > level_i ? log2_size_i - level_i : '0;
  assign mask      = CoordW'(((CoordW + 1)'(1) << size_log2) - (CoordW + 1)'(1));
  assign negative  = tap_i[TapW-1];
  assign periods   = tap_i >> size_log2;
  assign beyond    = periods != '0;  // t >= n, or t < 0
  assign reflect   = periods[0];     // bit log2 n of t: in the mirrored half
  assign low       = tap_i[CoordW-1:0] & mask;

  always_comb begin
    outside_o = 1'b0;
    if (clamp_i) begin
      coord_o = negative ? '0 : beyond ? mask : low;
    end else if (border_i) begin
      outside_o = beyond;
      coord_o   = beyond ? '0 : low;
    end else if (mirror_i) begin
      coord_o = reflect ? ~tap_i[CoordW-1:0] & mask : low;
    end else begin
      coord_o = low;
    end
  end

  // One grid position: n = 1 texel, or n <= 4 texels in one block.
  assign grid_one = block_grid_i ? size_log2 < Log2W'(3) : size_log2 == '0;
  always_comb begin
    if (grid_one) begin
      stored_o = {(CoordW - 1)'(0), block_grid_i ? tap_i[2] : tap_i[0]};
    end else begin
      stored_o = block_grid_i ? coord_o >> 2 : coord_o;
    end
  end

endmodule
