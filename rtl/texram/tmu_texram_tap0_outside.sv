/// Whether a request's first tap of level 0 lies outside its map (border mode), exactly golden
/// plan_sample(...).taps[0][0].outside at lambda 0 (golden/texram/trilinear.cpp): the
/// trilinear unit's own steps for that tap (tmu_trilinear_sphere for a sphere map's uN, vN,
/// tmu_trilinear_axis at level 0, tmu_trilinear_border on tap 0), computed beside the unit
/// because the unit does not output it. At lambda 0 every filter's first level is level 0.
///
/// The detail unit (tmu_texram_detail) asks it of the u-offset map's read: a texel outside a
/// border-mode texture has no detail region (docs/detail.md). Combinational.
///
/// Example: an 8 x 8 map, border mode on u, bilinear, u = 0.25 texels (raw 0x40): the first tap
/// is floor(0.25 - 0.5) = -1, outside; nearest: floor(0.25) = 0, inside.
module tmu_texram_tap0_outside #(
  /// The trilinear unit's widths (tmu_trilinear; golden texram::Widths S, W).
  parameter int unsigned SubTexelBits = 8,
  parameter int unsigned WeightBits   = 8
) (
  input  tmu_pkg::tex_coord_t       u_i,
  input  tmu_pkg::tex_coord_t       v_i,
  /// The map's configuration, as the trilinear unit's cfg_* (encodings: tmu_trilinear).
  input  tmu_pkg::mip_log2_t        log2_w_i,
  input  tmu_pkg::mip_log2_t        log2_h_i,
  input  tmu_pkg::tex_filter_t      filter_i,
  input  tmu_pkg::tex_border_t      border_u_i,
  input  tmu_pkg::tex_border_t      border_v_i,
  input  tmu_pkg::tex_addressing_t  addressing_i,
  input  logic                      block_grid_i,
  output logic                      outside_o
);

  localparam int unsigned TapW = 18;
  // tmu_trilinear's encodings.
  localparam tmu_pkg::tex_filter_t FilterNearest = 2'd0;
  localparam tmu_pkg::tex_border_t BorderClamp   = 2'd1;
  localparam tmu_pkg::tex_border_t BorderColour  = 2'd2;
  localparam tmu_pkg::tex_border_t BorderMirror  = 2'd3;

  tmu_pkg::tex_coord_t sphere_u, sphere_v, u, v;
  tmu_trilinear_sphere u_sphere_u (
    .coord_i(u_i), .flip_i(1'b0), .log2_i(log2_w_i), .coord_o(sphere_u)
  );
  tmu_trilinear_sphere u_sphere_v (
    .coord_i(v_i), .flip_i(1'b1), .log2_i(log2_h_i), .coord_o(sphere_v)
  );
  assign u = addressing_i ? sphere_u : u_i;
  assign v = addressing_i ? sphere_v : v_i;

  logic [1:0] outside;
  for (genvar a = 0; a < 2; a++) begin : gen_axis
    logic [TapW-1:0]         t0;
    logic [WeightBits-1:0]   weight;
    tmu_pkg::mip_coord_t     coord, stored;
    tmu_pkg::tex_border_t    border;
    assign border = a == 0 ? border_u_i : border_v_i;

    tmu_trilinear_axis #(.SubTexelBits(SubTexelBits), .WeightBits(WeightBits), .TapW(TapW)) u_axis (
      .coord_i   (a == 0 ? u : v),
      .level_i   ('0),
      .nearest_i (filter_i == FilterNearest),
      .t0_o      (t0),
      .weight_o  (weight)
    );
    tmu_trilinear_border #(.TapW(TapW)) u_border (
      .tap_i        (t0),
      .log2_size_i  (a == 0 ? log2_w_i : log2_h_i),
      .level_i      ('0),
      .clamp_i      (border == BorderClamp),
      .border_i     (border == BorderColour),
      .mirror_i     (border == BorderMirror),
      .block_grid_i (block_grid_i),
      .coord_o      (coord),
      .outside_o    (outside[a]),
      .stored_o     (stored)
    );

    // Only whether the tap is outside matters here.
    logic unused_tap;
    assign unused_tap = ^{weight, coord, stored};
  end

  assign outside_o = |outside;

endmodule
