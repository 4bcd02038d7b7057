/// The tau unit (004: EP0637814 claims 4-6 and 15; golden tau::TauUnit in
/// golden/tau/tau_unit.hpp, the specification): a fragment's parameter coordinates (s, t) ->
/// texture coordinates (u, v) through a grid of (u, v) nodes, linear (claim 5) or Catmull-Rom
/// (claim 6); the screen derivatives of (s, t) through the map's Jacobian -> r1 = d(u,v)/dx,
/// r2 = d(u,v)/dy, and lambda = log2 max(|r1|, |r2|) as the footprint setup computes it.
///
/// Node memory (tmu_tau_node_ram): 289 x 48 bits, single port, node (i, j) at i + 17 j. The
/// node port is ready only in Idle, when no sample is in progress: a write and a sample take
/// effect in the order they are presented (a sample reads the nodes every write accepted
/// before it wrote, and none accepted after it). A write to 289 .. 511 is dropped.
///
/// One sample at a time, a state per step (N nodes: 4 linear, 16 spline):
///   accept  s, t clamped, cell, x, x2 per axis (tmu_tau_axis) into registers
///   Weigh   x3 and the weights C, D per axis, the extrapolation folded in (tmu_tau_weights)
///   Read    N cycles: node k's address (clamped into the grid; a node the fold weights zero
///           is read and multiplied by zero) to the RAM, and its three tensor weights
///           Cs Ct, Ds Ct, Cs Dt into registers; the node k - 1 read the cycle before times
///           its weights into the six sums U, V, Us, Vs, Ut, Vt (six multipliers, the lanes)
///   Drain   the last node into the sums
///   Round   u, v = (U + 2^25) >>> 26 saturated; the Jacobian (Us + 2^23) >>> 24, 28 bits
///   Dx, Dy  r1, then r2: four lanes each, (Js d_s + Jt d_t + 2^17) >>> 18 saturated
///   Square  block-floating shift sh and the four squares on the lanes: smax
///   Log     lg(smax) (tmu_footprint_log2, the footprint setup's), lambda; the result into the
///           output register when it is free, and the next sample accepted in the same edge
/// Cycles per sample, back to back with the output taken: N + 7 (linear 11, spline 23).
/// Multipliers: 6 lanes of 28 x 24 bits (the node products; reused for r and the squares),
/// 3 of 16 x 16 (the tensor weights), 2 x 2 of 13 x 13 (x2 and x3 per axis).
///
/// Configuration (cfg_*): quasi-static, changed only while the unit is idle. Cells 0 act as 1,
/// above 16 as 16.
///
/// Example: cells 1 x 1, linear, nodes (0,0) = (0, 0), (1,0) = (256, 0), (0,1) = (0, 128),
/// (1,1) = (256, 128) texels; s = t = 0.5 cell, ds/dx = 1/256 cell, the rest 0: u = 128.0,
/// v = 64.0 texels, J = (256, 0; 0, 128) texels per cell, r1 = (1.0, 0), r2 = 0, lambda = 0.
module tmu_tau (
  input  logic                    clk_i,
  input  logic                    rst_ni,

  /// The grid: cells along s and t, the interpolation (0 linear, 1 Catmull-Rom).
  input  tmu_pkg::tau_cells_t     cfg_cells_s_i,
  input  tmu_pkg::tau_cells_t     cfg_cells_t_i,
  input  tmu_pkg::tau_interp_t    cfg_interp_i,

  /// Node write: node addr = i + 17 j <= (u, v).
  input  logic                    node_valid_i,
  output logic                    node_ready_o,
  input  tmu_pkg::tau_node_addr_t node_addr_i,
  input  tmu_pkg::tex_coord_t     node_u_i,
  input  tmu_pkg::tex_coord_t     node_v_i,

  /// A fragment: (s, t) and their screen derivatives.
  input  logic                    in_valid_i,
  output logic                    in_ready_o,
  input  tmu_pkg::pc_coord_t      in_s_i,
  input  tmu_pkg::pc_coord_t      in_t_i,
  input  tmu_pkg::pc_deriv_t      in_ds_dx_i,
  input  tmu_pkg::pc_deriv_t      in_dt_dx_i,
  input  tmu_pkg::pc_deriv_t      in_ds_dy_i,
  input  tmu_pkg::pc_deriv_t      in_dt_dy_i,

  /// Its texture coordinates, derivative vectors and level of detail.
  output logic                    out_valid_o,
  input  logic                    out_ready_i,
  output tmu_pkg::tex_coord_t     out_u_o,
  output tmu_pkg::tex_coord_t     out_v_o,
  output tmu_pkg::tex_deriv_t     out_r1u_o,
  output tmu_pkg::tex_deriv_t     out_r1v_o,
  output tmu_pkg::tex_deriv_t     out_r2u_o,
  output tmu_pkg::tex_deriv_t     out_r2v_o,
  output tmu_pkg::lod_t           out_lambda_o
);

  localparam int unsigned CW  = tmu_pkg::TexCoordW;  // 24: nodes, u, v, r
  localparam int unsigned DW  = tmu_pkg::PcDerivW;   // 24
  localparam int unsigned WW  = 16;                  // an axis weight (tmu_tau_weights)
  localparam int unsigned AW  = 28;                  // a lane's first operand: w or J
  localparam int unsigned BW  = 24;                  // its second: a node, a derivative
  localparam int unsigned PW  = AW + BW;             // a lane's product
  localparam int unsigned SW  = 53;                  // the sums: |U| < 2^50, |Us| < 2^51
  localparam int unsigned JW  = 28;                  // the Jacobian, SQ18.10
  localparam int unsigned LodW = tmu_pkg::LodW;      // 14
  localparam int unsigned SqW = 25;                  // a squared length of 12-bit components

  if (CW != 24 || DW != 24 || tmu_pkg::TexCoordFrac != 8 || tmu_pkg::TexDerivW != 24 ||
      tmu_pkg::LodFrac != 8 || tmu_pkg::TauMaxCells != 16) begin : gen_check
    $error("tmu_tau: built for SQ16.8 nodes and r, SQ8.16 (s, t), Lod SQ6.8, 16 cells");
  end

  typedef enum logic [3:0] {
    Idle   = 4'd0,
    Weigh  = 4'd1,
    Read   = 4'd2,
    Drain  = 4'd3,
    Round  = 4'd4,
    Dx     = 4'd5,
    Dy     = 4'd6,
    Square = 4'd7,
    Log    = 4'd8
  } state_e;

  state_e state_q, state_d;

  // ---- Configuration: cells 1..16 ----------------------------------------------------------

  logic [4:0] cells_s, cells_t;
  logic       spline;

  function automatic logic [4:0] effective(input tmu_pkg::tau_cells_t cells);
    if (cells == '0) effective = 5'd1;
    else if (cells > 5'd16) effective = 5'd16;
    else effective = 5'(cells);
  endfunction

  assign cells_s = effective(cfg_cells_s_i);
  assign cells_t = effective(cfg_cells_t_i);
  assign spline  = cfg_interp_i == 1'b1;

  // ---- Handshakes --------------------------------------------------------------------------

  logic out_valid_q, out_free, in_fire, node_fire, done;

  assign out_free     = !out_valid_q || out_ready_i;
  // The result leaves Log into a free output register; the next sample enters on that edge.
  assign done         = state_q == Log && out_free;
  assign in_ready_o   = state_q == Idle || done;
  assign in_fire      = in_valid_i && in_ready_o;
  assign node_ready_o = state_q == Idle;
  assign node_fire    = node_valid_i && node_ready_o;

  // ---- Accept: clamp, cell, fraction, square per axis ----------------------------------------

  logic [3:0]  cell_s, cell_t;
  logic [12:0] x_s, x_t, x2_s, x2_t;

  tmu_tau_axis u_axis_s (
    .coord_i (in_s_i),
    .cells_i (cells_s),
    .cell_o  (cell_s),
    .x_o     (x_s),
    .x2_o    (x2_s)
  );
  tmu_tau_axis u_axis_t (
    .coord_i (in_t_i),
    .cells_i (cells_t),
    .cell_o  (cell_t),
    .x_o     (x_t),
    .x2_o    (x2_t)
  );

  logic [3:0]         cell_s_q, cell_t_q;
  logic [12:0]        x_s_q, x_t_q, x2_s_q, x2_t_q;
  tmu_pkg::pc_deriv_t ds_dx_q, dt_dx_q, ds_dy_q, dt_dy_q;

  // ---- Weigh: the weights per axis ---------------------------------------------------------

  logic signed [5:0] first_s, first_t;
  logic [4*WW-1:0]   c_s, d_s, c_t, d_t;

  tmu_tau_weights u_weights_s (
    .x_i      (x_s_q),
    .x2_i     (x2_s_q),
    .cell_i   (cell_s_q),
    .cells_i  (cells_s),
    .interp_i (cfg_interp_i),
    .first_o  (first_s),
    .c_o      (c_s),
    .d_o      (d_s)
  );
  tmu_tau_weights u_weights_t (
    .x_i      (x_t_q),
    .x2_i     (x2_t_q),
    .cell_i   (cell_t_q),
    .cells_i  (cells_t),
    .interp_i (cfg_interp_i),
    .first_o  (first_t),
    .c_o      (c_t),
    .d_o      (d_t)
  );

  logic signed [5:0] first_s_q, first_t_q;
  logic [4*WW-1:0]   c_s_q, d_s_q, c_t_q, d_t_q;

  // ---- Read: node k's address and tensor weights; node k - 1 into the sums -------------------

  logic [3:0]                    k_q;
  logic                          last_read;
  logic [1:0]                    a_idx, b_idx;
  logic signed [5:0]             i_raw, j_raw;
  logic [4:0]                    i_node, j_node;
  tmu_pkg::tau_node_addr_t       read_addr, ram_addr;
  logic signed [WW-1:0]          cs, ds, ct, dt;
  logic signed [AW-1:0]          w_full, ws_full, wt_full;
  logic signed [AW-1:0]          w_q, ws_q, wt_q;
  logic [2*CW-1:0]               rdata;

  assign last_read = k_q == (spline ? 4'd15 : 4'd3);
  assign a_idx     = spline ? k_q[1:0] : {1'b0, k_q[0]};
  assign b_idx     = spline ? k_q[3:2] : {1'b0, k_q[1]};
  assign i_raw     = first_s_q + 6'(a_idx);
  assign j_raw     = first_t_q + 6'(b_idx);

  // Clamped into the grid: only a node the fold weights zero is ever moved.
  function automatic logic [4:0] clamp_index(input logic signed [5:0] n, input logic [4:0] top);
    if (n < 0) clamp_index = '0;
    else if (n > $signed({1'b0, top})) clamp_index = top;
    else clamp_index = n[4:0];
  endfunction

  assign i_node    = clamp_index(i_raw, cells_s);
  assign j_node    = clamp_index(j_raw, cells_t);
  assign read_addr = 9'(i_node) + 9'({j_node, 4'b0}) + 9'(j_node);  // i + 17 j
  assign ram_addr  = state_q == Read ? read_addr : node_addr_i;

  assign cs = c_s_q[32'(a_idx)*WW +: WW];
  assign ds = d_s_q[32'(a_idx)*WW +: WW];
  assign ct = c_t_q[32'(b_idx)*WW +: WW];
  assign dt = d_t_q[32'(b_idx)*WW +: WW];
  // |Cs Ct| <= 2^26, |Ds Ct|, |Cs Dt| < 2^27 (tmu_tau_weights): exact in AW = 28 bits.
  assign w_full  = AW'(cs) * AW'(ct);
  assign ws_full = AW'(ds) * AW'(ct);
  assign wt_full = AW'(cs) * AW'(dt);

  tmu_tau_node_ram u_ram (
    .clk_i   (clk_i),
    .we_i    (node_fire),
    .addr_i  (ram_addr),
    .wdata_i ({node_v_i, node_u_i}),
    .rdata_o (rdata)
  );

  // ---- The six lanes: node products, then r, then squares -------------------------------------

  logic signed [AW-1:0] lane_a [6];
  logic signed [BW-1:0] lane_b [6];
  logic signed [PW-1:0] lane_p [6];
  logic signed [BW-1:0] node_u, node_v;
  logic                 accumulate;

  // Block-floating magnitudes of r1, r2 (the footprint setup's: 12 significant bits).
  logic [4*CW-1:0] r_mag;
  logic [CW-1:0]   r_or;
  logic [4:0]      bitlen, sh;
  logic [4*12-1:0] r_short;

  tmu_pkg::tex_deriv_t r1u_q, r1v_q, r2u_q, r2v_q;
  tmu_pkg::tex_coord_t  u_q, v_q;
  logic signed [JW-1:0] jus_q, jvs_q, jut_q, jvt_q;

  assign node_u = rdata[CW-1:0];
  assign node_v = rdata[2*CW-1:CW];
  assign accumulate = (state_q == Read && k_q != '0) || state_q == Drain;

  logic [4*CW-1:0] r_all;
  assign r_all = {r2v_q, r2u_q, r1v_q, r1u_q};

  always_comb begin
    r_or = '0;
    for (int c = 0; c < 4; c++) begin
      // |c| of a 24-bit two's complement value fits 24 bits unsigned (|-2^23| = 2^23).
      r_mag[c*CW +: CW] = r_all[c*CW + CW-1] ? -r_all[c*CW +: CW] : r_all[c*CW +: CW];
      r_or = r_or | r_mag[c*CW +: CW];
    end
    bitlen = '0;
    for (int b = 0; b < CW; b++) begin
      if (r_or[b]) bitlen = 5'(b + 1);
    end
    sh = bitlen > 5'd12 ? bitlen - 5'd12 : '0;
    for (int c = 0; c < 4; c++) r_short[c*12 +: 12] = 12'(r_mag[c*CW +: CW] >> sh);
  end

  always_comb begin
    for (int l = 0; l < 6; l++) begin
      lane_a[l] = '0;
      lane_b[l] = '0;
    end
    case (state_q)
      Read, Drain: begin
        lane_a[0] = w_q;  lane_b[0] = node_u;
        lane_a[1] = w_q;  lane_b[1] = node_v;
        lane_a[2] = ws_q; lane_b[2] = node_u;
        lane_a[3] = ws_q; lane_b[3] = node_v;
        lane_a[4] = wt_q; lane_b[4] = node_u;
        lane_a[5] = wt_q; lane_b[5] = node_v;
      end
      Dx, Dy: begin
        lane_a[0] = jus_q; lane_b[0] = state_q == Dx ? ds_dx_q : ds_dy_q;
        lane_a[1] = jut_q; lane_b[1] = state_q == Dx ? dt_dx_q : dt_dy_q;
        lane_a[2] = jvs_q; lane_b[2] = state_q == Dx ? ds_dx_q : ds_dy_q;
        lane_a[3] = jvt_q; lane_b[3] = state_q == Dx ? dt_dx_q : dt_dy_q;
      end
      Square: begin
        for (int l = 0; l < 4; l++) begin
          lane_a[l] = AW'(r_short[l*12 +: 12]);
          lane_b[l] = BW'(r_short[l*12 +: 12]);
        end
      end
      default: ;
    endcase
    for (int l = 0; l < 6; l++) lane_p[l] = PW'(lane_a[l]) * PW'(lane_b[l]);
  end

  logic signed [SW-1:0] sum_u_q, sum_v_q, sum_us_q, sum_vs_q, sum_ut_q, sum_vt_q;

  // ---- Round: u, v and the Jacobian --------------------------------------------------------

  // Saturation of a wide signed value to n bits (n <= 32).
  function automatic logic [31:0] saturate(input logic signed [63:0] value, input int n);
    logic signed [63:0] hi, lo;
    hi = (64'sd1 <<< (n - 1)) - 64'sd1;
    lo = -(64'sd1 <<< (n - 1));
    if (value > hi) saturate = 32'(hi);
    else if (value < lo) saturate = 32'(lo);
    else saturate = 32'(value);
  endfunction

  logic signed [SW-1:0] u_rounded, v_rounded, jus_r, jvs_r, jut_r, jvt_r;

  assign u_rounded = (sum_u_q + (SW'(1) <<< 25)) >>> 26;
  assign v_rounded = (sum_v_q + (SW'(1) <<< 25)) >>> 26;
  assign jus_r     = (sum_us_q + (SW'(1) <<< 23)) >>> 24;
  assign jvs_r     = (sum_vs_q + (SW'(1) <<< 23)) >>> 24;
  assign jut_r     = (sum_ut_q + (SW'(1) <<< 23)) >>> 24;
  assign jvt_r     = (sum_vt_q + (SW'(1) <<< 23)) >>> 24;

  // ---- Dx, Dy: r = (Js d_s + Jt d_t + 2^17) >>> 18, saturated ---------------------------------

  logic signed [PW:0] ru_sum, rv_sum;
  logic signed [PW:0] ru_rounded, rv_rounded;

  assign ru_sum     = (PW + 1)'(lane_p[0]) + (PW + 1)'(lane_p[1]);
  assign rv_sum     = (PW + 1)'(lane_p[2]) + (PW + 1)'(lane_p[3]);
  assign ru_rounded = (ru_sum + ((PW + 1)'(1) <<< 17)) >>> 18;
  assign rv_rounded = (rv_sum + ((PW + 1)'(1) <<< 17)) >>> 18;

  // ---- Square: smax; Log: lambda ------------------------------------------------------------

  logic [SqW-1:0] s1, s2, smax_q;
  logic [4:0]     sh_q;

  assign s1 = SqW'(lane_p[0]) + SqW'(lane_p[1]);
  assign s2 = SqW'(lane_p[2]) + SqW'(lane_p[3]);

  localparam int unsigned EW = $clog2(SqW);
  localparam int unsigned VW = $clog2(SqW + 1) + 8;
  logic          lg_zero;
  logic [EW-1:0] unused_lg_exp;
  logic [VW-1:0] lg;

  tmu_footprint_log2 #(.XW(SqW), .TableBits(7), .LogFracBits(8)) u_log2 (
    .x_i     (smax_q),
    .zero_o  (lg_zero),
    .exp_o   (unused_lg_exp),
    .value_o (lg)
  );

  // In 9 fraction bits: lg + (2 sh - 16) 2^8; rounded half up to 8: (x + 1) >>> 1.
  localparam int unsigned LW = 16;
  logic signed [LW-1:0] lambda9, lambda8;
  tmu_pkg::lod_t        lambda;

  assign lambda9 = LW'(lg) + ((LW'({sh_q, 1'b0}) - LW'(16)) <<< 8);
  assign lambda8 = (lambda9 + LW'(1)) >>> 1;
  assign lambda  = lg_zero ? LodW'(-(64'sd1 <<< (LodW - 1))) : LodW'(saturate(64'(lambda8), LodW));

  // ---- Control ------------------------------------------------------------------------------

  always_comb begin
    state_d = state_q;
    case (state_q)
      Idle:    if (in_fire) state_d = Weigh;
      Weigh:   state_d = Read;
      Read:    if (last_read) state_d = Drain;
      Drain:   state_d = Round;
      Round:   state_d = Dx;
      Dx:      state_d = Dy;
      Dy:      state_d = Square;
      Square:  state_d = Log;
      Log:     if (done) state_d = in_fire ? Weigh : Idle;
      default: state_d = Idle;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q     <= Idle;
      out_valid_q <= 1'b0;
    end else begin
      state_q     <= state_d;
      out_valid_q <= done || (out_valid_q && !out_ready_i);
    end
  end

  // Data registers: read only in the states that follow their load, or while out_valid_q.
  tmu_pkg::tex_coord_t out_u_q, out_v_q;
  tmu_pkg::tex_deriv_t out_r1u_q, out_r1v_q, out_r2u_q, out_r2v_q;
  tmu_pkg::lod_t       out_lambda_q;

  always_ff @(posedge clk_i) begin
    if (in_fire) begin
      cell_s_q <= cell_s;
      cell_t_q <= cell_t;
      x_s_q    <= x_s;
      x_t_q    <= x_t;
      x2_s_q   <= x2_s;
      x2_t_q   <= x2_t;
      ds_dx_q  <= in_ds_dx_i;
      dt_dx_q  <= in_dt_dx_i;
      ds_dy_q  <= in_ds_dy_i;
      dt_dy_q  <= in_dt_dy_i;
    end
    if (state_q == Weigh) begin
      first_s_q <= first_s;
      first_t_q <= first_t;
      c_s_q     <= c_s;
      d_s_q     <= d_s;
      c_t_q     <= c_t;
      d_t_q     <= d_t;
      k_q       <= '0;
      sum_u_q   <= '0;
      sum_v_q   <= '0;
      sum_us_q  <= '0;
      sum_vs_q  <= '0;
      sum_ut_q  <= '0;
      sum_vt_q  <= '0;
    end
    if (state_q == Read) begin
      k_q  <= k_q + 4'd1;
      w_q  <= w_full;
      ws_q <= ws_full;
      wt_q <= wt_full;
    end
    if (accumulate) begin
      sum_u_q  <= sum_u_q + SW'(lane_p[0]);
      sum_v_q  <= sum_v_q + SW'(lane_p[1]);
      sum_us_q <= sum_us_q + SW'(lane_p[2]);
      sum_vs_q <= sum_vs_q + SW'(lane_p[3]);
      sum_ut_q <= sum_ut_q + SW'(lane_p[4]);
      sum_vt_q <= sum_vt_q + SW'(lane_p[5]);
    end
    if (state_q == Round) begin
      u_q   <= CW'(saturate(64'(u_rounded), CW));
      v_q   <= CW'(saturate(64'(v_rounded), CW));
      jus_q <= JW'(saturate(64'(jus_r), JW));
      jvs_q <= JW'(saturate(64'(jvs_r), JW));
      jut_q <= JW'(saturate(64'(jut_r), JW));
      jvt_q <= JW'(saturate(64'(jvt_r), JW));
    end
    if (state_q == Dx) begin
      r1u_q <= CW'(saturate(64'(ru_rounded), CW));
      r1v_q <= CW'(saturate(64'(rv_rounded), CW));
    end
    if (state_q == Dy) begin
      r2u_q <= CW'(saturate(64'(ru_rounded), CW));
      r2v_q <= CW'(saturate(64'(rv_rounded), CW));
    end
    if (state_q == Square) begin
      smax_q <= s1 > s2 ? s1 : s2;
      sh_q   <= sh;
    end
    if (done) begin
      out_u_q      <= u_q;
      out_v_q      <= v_q;
      out_r1u_q    <= r1u_q;
      out_r1v_q    <= r1v_q;
      out_r2u_q    <= r2u_q;
      out_r2v_q    <= r2v_q;
      out_lambda_q <= lambda;
    end
  end

  assign out_valid_o  = out_valid_q;
  assign out_u_o      = out_u_q;
  assign out_v_o      = out_v_q;
  assign out_r1u_o    = out_r1u_q;
  assign out_r1v_o    = out_r1v_q;
  assign out_r2u_o    = out_r2u_q;
  assign out_r2v_o    = out_r2v_q;
  assign out_lambda_o = out_lambda_q;

endmodule
