/// Per-tap substitution of one tap (golden plan_clip_sample, per tap, in
/// golden/clipmap/clipmap.cpp, the specification): a tap of clipped level L at virtual texel
/// (x, y) that its tile does not hold is read at the first coarser level m whose tile holds
/// (x >> (m - L), y >> (m - L)), or at the first whole level C when none does; a held tap, a
/// tap of a whole level, a tap outside the texture and every tap when substitute_i is low
/// stay as they are. Combinational: one region test per clipped level above L, side by side
/// (the regions are registers; the tap is shifted once, into level-0 units), then a priority
/// choice.
///
/// Example: C = 3, L = 0, (x, y) = (70, 9), regions: level 0 [40, 72) x [10, 42), level 1
/// [20, 52) x [0, 32): level 0 does not hold (70, 9) (9 < 10), level 1 holds (35, 4): the tap
/// is read at level 1, texel (35, 4), substituted.
// Not traced: its internals are one per level (and per tap) and its results are the top's
// wires (holds, tap_level, tap_x, tap_y), which are; tracing them all tripled the model's code.
// verilator tracing_off
module tmu_clip_tap #(
  /// Region register sets (levels 0 .. Levels - 1 can be clipped).
  parameter int unsigned Levels = 13
) (
  input  logic                          substitute_i,
  input  logic                          outside_i,
  /// C: the clipped levels (levels from C up are whole).
  input  tmu_pkg::mip_level_t           clipped_i,
  input  tmu_pkg::mip_level_t           level_i,
  input  tmu_pkg::clip_coord_t          x_i,
  input  tmu_pkg::clip_coord_t          y_i,
  /// Every level's region: level l's x0, y0, x1, y1 in field 4 l + k (k = 0..3) of ClipBound
  /// bits each.
  input  logic [4*Levels*tmu_pkg::ClipBoundW-1:0] region_i,
  output tmu_pkg::mip_level_t           level_o,
  output tmu_pkg::clip_coord_t          x_o,
  output tmu_pkg::clip_coord_t          y_o,
  output logic                          substituted_o
);

  localparam int unsigned LW = tmu_pkg::MipLevelW;
  localparam int unsigned BW = tmu_pkg::ClipBoundW;

  // here[m]: level m's tile holds (x, y) (the tap's own level's test); holds[m]: it holds
  // (x >> (m - L), y >> (m - L)), for a clipped level m above L. Tested without a shifter per
  // level: x >> k >= x0 <=> x << L >= x0 << m, and x >> k < x1 <=> x << L < x1 << m (x, x0, x1
  // whole numbers, k = m - L), so the tap is shifted once into level-0 units and each level's
  // bounds by its constant m (wiring).
  localparam int unsigned WW = BW + Levels - 1;  // x0 << m, m < Levels; x << L, L < m
  logic [Levels-1:0] here, holds;
  logic [WW-1:0]     x_l0, y_l0;
  assign x_l0 = WW'(x_i) << level_i;
  assign y_l0 = WW'(y_i) << level_i;

  function automatic logic in_rect(tmu_pkg::clip_coord_t x, tmu_pkg::clip_coord_t y,
                                  tmu_pkg::clip_bound_t x0, tmu_pkg::clip_bound_t y0,
                                  tmu_pkg::clip_bound_t x1, tmu_pkg::clip_bound_t y1);
    in_rect = {1'b0, x} >= x0 && {1'b0, x} < x1 && {1'b0, y} >= y0 && {1'b0, y} < y1;
  endfunction

  for (genvar m = 0; m < Levels; m++) begin : gen_level
    tmu_pkg::clip_bound_t x0, y0, x1, y1;
    assign {y1, x1, y0, x0} = region_i[4*m*BW +: 4*BW];
    assign here[m]  = in_rect(x_i, y_i, x0, y0, x1, y1);
    if (m == 0) begin : gen_first  // no level is below level 0
      assign holds[m] = 1'b0;
    end else begin : gen_above
      assign holds[m] = level_i < LW'(m) && LW'(m) < clipped_i &&
                        x_l0 >= (WW'(x0) << m) && x_l0 < (WW'(x1) << m) &&
                        y_l0 >= (WW'(y0) << m) && y_l0 < (WW'(y1) << m);
    end
  end

  logic held_here;
  always_comb begin
    held_here = level_i >= clipped_i;
    for (int m = 0; m < Levels; m++) begin
      if (LW'(m) == level_i) held_here = held_here || here[m];
    end
  end

  tmu_pkg::mip_level_t chosen;
  always_comb begin
    chosen = clipped_i;  // no coarser tile holds it: the first whole level
    for (int m = Levels - 1; m >= 0; m--) begin
      if (holds[m]) chosen = LW'(m);
    end
  end

  assign substituted_o = substitute_i && !outside_i && !held_here;
  assign level_o       = substituted_o ? chosen : level_i;
  assign x_o           = x_i >> (level_o - level_i);
  assign y_o           = y_i >> (level_o - level_i);

endmodule
