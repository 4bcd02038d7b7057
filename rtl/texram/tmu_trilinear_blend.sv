/// The trilinear interpolator and the output and combination stage of the TEXRAM (000 §5,
/// Fig. 8: 818 and 820; §6, eq. 5), exactly as texram::blend_taps and texram::combine
/// (golden/texram/trilinear.cpp). A pipeline of four stages with valid/ready:
///
///   X  per level j and channel: top = lerp(c00, c10, wx_j), bottom = lerp(c01, c11, wx_j)
///   Y  per level: level value = lerp(top, bottom, wy_j)
///   Z  lerp(level 0, level 1, wl), rounded once half up: + 2^(3W-1), drop 3W bits
///   O  eq. 5: per channel round(T M / 255) with M = k_T (constant) or I_d (shade), or T;
///      the output register
///
/// Every lerp is exact (tmu_trilinear_lerp): the Z value is the golden model's weighted sum
/// of all eight taps scaled by 2^3W. Bilinear and nearest come in with wl = 0 (and nearest
/// with wx = wy = 0 too): then the sum is 2^W times the bilinear one, or 2^3W times tap 00,
/// and the one rounding gives exactly the golden bilinear (2W bits dropped) or the tap itself.
///
/// Each stage takes a new sample when it is empty or passes its own on; out_valid_o and
/// out_rgba_o come from the output register: one sample per clock, 4 cycles latency.
///
/// Example (W = 8, one channel): level 0 taps 10, 20, 30, 40, wx = 0x80, wy = 0x40; level 1
/// all 100; wl = 0x80: level 0 = 20.0, level 1 = 100.0, T = 60; with M = 128: 30.
module tmu_trilinear_blend #(
  /// Bits of the filter and level weights (1..8).
  parameter int unsigned WeightBits = 8
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  /// eq. 5 selection, decoded (none set: one), and the constant k_T.
  input  logic                 combine_constant_i,
  input  logic                 combine_shade_i,
  input  tmu_pkg::rgba8888_t   constant_rgba_i,

  /// The eight tap colours (tap 4 j + k of level j at [(4 j + k) * 32 +: 32]; k = 0 (x0, y0),
  /// 1 (x1, y0), 2 (x0, y1), 3 (x1, y1)), the weights of x1 and y1 per level (level j at
  /// [j * W +: W]), the weight of level 1, and the shaded intensity I_d.
  input  logic                 in_valid_i,
  output logic                 in_ready_o,
  input  logic [8*tmu_pkg::Rgba8888W-1:0] in_colours_i,
  input  logic [2*WeightBits-1:0] in_wx_i,
  input  logic [2*WeightBits-1:0] in_wy_i,
  input  logic [WeightBits-1:0]   in_wl_i,
  input  tmu_pkg::rgba8888_t   in_shade_i,

  /// The sample.
  output logic                 out_valid_o,
  input  logic                 out_ready_i,
  output tmu_pkg::rgba8888_t   out_rgba_o
);

  localparam int unsigned W   = WeightBits;
  localparam int unsigned ChW = tmu_pkg::ChannelW;        // 8
  localparam int unsigned Chs = tmu_pkg::Rgba8888W / ChW;  // 4
  localparam int unsigned CW  = tmu_pkg::Rgba8888W;
  localparam int unsigned XW  = ChW + W;                   // top / bottom row value
  localparam int unsigned YW  = ChW + 2 * W;               // level value
  localparam int unsigned ZW  = ChW + 3 * W;               // trilinear sum
  localparam logic [ZW-1:0] RoundHalf = ZW'(1) << (3 * W - 1);

  if (W < 1 || W > 8) begin : gen_check
    $error("tmu_trilinear_blend: WeightBits must be 1..8");
  end

  // ---- Stage registers --------------------------------------------------------------------

  logic                 x_valid_q, y_valid_q, z_valid_q, o_valid_q;
  logic                 x_ready, y_ready, z_ready, o_ready;
  logic                 x_load, y_load, z_load, o_load;
  // X: top and bottom per level and channel, index 2 (4 j + ch) + {0 top, 1 bottom}.
  logic [16*XW-1:0]     x_rows_d, x_rows_q;
  logic [2*W-1:0]       x_wy_q;
  logic [W-1:0]         x_wl_q, y_wl_q;
  tmu_pkg::rgba8888_t   x_shade_q, y_shade_q, z_shade_q;
  // Y: level value per level and channel, index 4 j + ch.
  logic [8*YW-1:0]      y_levels_d, y_levels_q;
  // Z: the texture value T.
  tmu_pkg::rgba8888_t   z_rgba_d, z_rgba_q;
  // O: the combined colour.
  tmu_pkg::rgba8888_t   o_rgba_d, o_rgba_q;

  assign o_ready    = !o_valid_q || out_ready_i;
  assign z_ready    = !z_valid_q || o_ready;
  assign y_ready    = !y_valid_q || z_ready;
  assign x_ready    = !x_valid_q || y_ready;
  assign in_ready_o = x_ready;

  assign x_load = in_valid_i && x_ready;
  assign y_load = x_valid_q && y_ready;
  assign z_load = y_valid_q && z_ready;
  assign o_load = z_valid_q && o_ready;

  // ---- X: the row lerps -------------------------------------------------------------------

  for (genvar j = 0; j < 2; j++) begin : gen_x_level
    for (genvar ch = 0; ch < Chs; ch++) begin : gen_x_channel
      for (genvar r = 0; r < 2; r++) begin : gen_x_row  // r = 0: taps 0, 1; r = 1: taps 2, 3
        tmu_trilinear_lerp #(.AW(ChW), .FW(W)) u_lerp (
          .a_i (in_colours_i[(4*j + 2*r)*CW + ch*ChW +: ChW]),
          .b_i (in_colours_i[(4*j + 2*r + 1)*CW + ch*ChW +: ChW]),
          .f_i (in_wx_i[j*W +: W]),
          .c_o (x_rows_d[(2*(4*j + ch) + r)*XW +: XW])
        );
      end
    end
  end

  // ---- Y: the column lerps ----------------------------------------------------------------

  for (genvar j = 0; j < 2; j++) begin : gen_y_level
    for (genvar ch = 0; ch < Chs; ch++) begin : gen_y_channel
      tmu_trilinear_lerp #(.AW(XW), .FW(W)) u_lerp (
        .a_i (x_rows_q[(2*(4*j + ch))*XW +: XW]),
        .b_i (x_rows_q[(2*(4*j + ch) + 1)*XW +: XW]),
        .f_i (x_wy_q[j*W +: W]),
        .c_o (y_levels_d[(4*j + ch)*YW +: YW])
      );
    end
  end

  // ---- Z: the level lerp and the one rounding ---------------------------------------------

  for (genvar ch = 0; ch < Chs; ch++) begin : gen_z_channel
    logic [ZW-1:0] sum, rounded;
    tmu_trilinear_lerp #(.AW(YW), .FW(W)) u_lerp (
      .a_i (y_levels_q[ch*YW +: YW]),
      .b_i (y_levels_q[(4 + ch)*YW +: YW]),
      .f_i (y_wl_q),
      .c_o (sum)
    );
    assign rounded                = sum + RoundHalf;
    assign z_rgba_d[ch*ChW +: ChW] = rounded[ZW-1 -: ChW];

    logic unused_bits;
    assign unused_bits = ^rounded[3*W-1:0];
  end

  // ---- O: eq. 5 ---------------------------------------------------------------------------

  tmu_pkg::rgba8888_t modulator, modulated;
  assign modulator = combine_constant_i ? constant_rgba_i : z_shade_q;

  // round(T M / 255) per channel, exactly as texram::mul255.
  for (genvar ch = 0; ch < Chs; ch++) begin : gen_o_channel
    tmu_mul255 u_mul255 (
      .t_i (z_rgba_q[ch*ChW +: ChW]),
      .m_i (modulator[ch*ChW +: ChW]),
      .p_o (modulated[ch*ChW +: ChW])
    );
  end

  assign o_rgba_d = combine_constant_i || combine_shade_i ? modulated : z_rgba_q;

  // ---- Flops ------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      x_valid_q <= 1'b0;
      y_valid_q <= 1'b0;
      z_valid_q <= 1'b0;
      o_valid_q <= 1'b0;
    end else begin
      x_valid_q <= x_load || (x_valid_q && !y_ready);
      y_valid_q <= y_load || (y_valid_q && !z_ready);
      z_valid_q <= z_load || (z_valid_q && !o_ready);
      o_valid_q <= o_load || (o_valid_q && !out_ready_i);
    end
  end

  // Data registers are read only while their stage is valid: no reset.
  always_ff @(posedge clk_i) begin
    if (x_load) begin
      x_rows_q  <= x_rows_d;
      x_wy_q    <= in_wy_i;
      x_wl_q    <= in_wl_i;
      x_shade_q <= in_shade_i;
    end
    if (y_load) begin
      y_levels_q <= y_levels_d;
      y_wl_q     <= x_wl_q;
      y_shade_q  <= x_shade_q;
    end
    if (z_load) begin
      z_rgba_q  <= z_rgba_d;
      z_shade_q <= y_shade_q;
    end
    if (o_load) o_rgba_q <= o_rgba_d;
  end

  assign out_valid_o = o_valid_q;
  assign out_rgba_o  = o_rgba_q;

endmodule
