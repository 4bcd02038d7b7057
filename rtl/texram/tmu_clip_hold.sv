/// Whether one clipped level's tile holds a sample point's taps there (golden holds_point in
/// golden/clipmap/clipmap.cpp, the specification): the point's taps at level Level (its first
/// tap t0 per axis from tmu_trilinear_axis, and t0 + 1 unless nearest), each resolved by the
/// virtual texture's border operator (side 2^(V - Level)), and every tap that reads (a border
/// tap outside the texture reads nothing) inside the level's region [x0, x1) x [y0, y1).
/// Combinational; tmu_clipmap has one per clipped level, side by side.
///
/// Example: Level 1, V = 8, region [10, 42) x [0, 32), bilinear, u = 20.0 (raw 0x1400), v = 3.0:
/// at level 1 u is 10.0, taps 9 and 10: 9 < 10, the tile does not hold the point.
// Not traced: its internals are one per level (and per tap) and its results are the top's
// wires (holds, tap_level, tap_x, tap_y), which are; tracing them all tripled the model's code.
// verilator tracing_off
module tmu_clip_hold #(
  parameter int unsigned Level = 0
) (
  input  tmu_pkg::tex_coord_t    u_i,
  input  tmu_pkg::tex_coord_t    v_i,
  input  logic                   nearest_i,
  /// The virtual texture: log2 of its side, and the border operator per axis (decoded).
  input  tmu_pkg::clip_log2_t    log2_virtual_i,
  input  logic                   clamp_u_i,
  input  logic                   border_u_i,
  input  logic                   mirror_u_i,
  input  logic                   clamp_v_i,
  input  logic                   border_v_i,
  input  logic                   mirror_v_i,
  /// The level's region.
  input  tmu_pkg::clip_bound_t   x0_i,
  input  tmu_pkg::clip_bound_t   y0_i,
  input  tmu_pkg::clip_bound_t   x1_i,
  input  tmu_pkg::clip_bound_t   y1_i,
  output logic                   holds_o
);

  localparam int unsigned TapW   = 18;
  localparam int unsigned CoordW = tmu_pkg::ClipCoordW;  // 15: a virtual level's texel
  localparam tmu_pkg::mip_level_t L = tmu_pkg::MipLevelW'(Level);

  logic [TapW-1:0]   t0 [2];      // per axis (0 u, 1 v)
  logic [CoordW-1:0] coord [2][2];  // per axis and tap
  logic              outside [2][2];
  logic              in_region [2][2];

  for (genvar a = 0; a < 2; a++) begin : gen_axis
    logic unused_weight;
    logic [7:0] weight;
    tmu_trilinear_axis #(.TapW(TapW)) u_axis (
      .coord_i  (a == 0 ? u_i : v_i),
      .level_i  (L),
      .nearest_i(nearest_i),
      .t0_o     (t0[a]),
      .weight_o (weight)
    );
    assign unused_weight = ^weight;
    for (genvar i = 0; i < 2; i++) begin : gen_tap
      logic [CoordW-1:0] stored;  // the pyramid's stored coordinate: not the clip-map's
      logic              unused_stored;
      tmu_trilinear_border #(.TapW(TapW), .CoordW(CoordW)) u_border (
        .tap_i        (t0[a] + TapW'(i)),
        .log2_size_i  (log2_virtual_i),
        .level_i      (L),
        .clamp_i      (a == 0 ? clamp_u_i : clamp_v_i),
        .border_i     (a == 0 ? border_u_i : border_v_i),
        .mirror_i     (a == 0 ? mirror_u_i : mirror_v_i),
        .block_grid_i (1'b0),
        .coord_o      (coord[a][i]),
        .outside_o    (outside[a][i]),
        .stored_o     (stored)
      );
      assign unused_stored = ^stored;
      assign in_region[a][i] = a == 0
          ? {1'b0, coord[a][i]} >= x0_i && {1'b0, coord[a][i]} < x1_i
          : {1'b0, coord[a][i]} >= y0_i && {1'b0, coord[a][i]} < y1_i;
    end
  end

  // Tap (i, j) = (x_i, y_j): held when it reads nothing or the region holds it.
  always_comb begin
    holds_o = 1'b1;
    for (int j = 0; j < 2; j++) begin
      for (int i = 0; i < 2; i++) begin
        if (i == 0 && j == 0 || !nearest_i) begin
          holds_o = holds_o && (outside[0][i] || outside[1][j] || in_region[0][i] && in_region[1][j]);
        end
      end
    end
  end

endmodule
