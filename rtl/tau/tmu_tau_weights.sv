/// One axis's weights of the tau unit (golden tau::axis_weights, step 2; the extrapolation of
/// step 3 folded into them). Combinational.
///
/// From the fraction x and x2 (tmu_tau_axis), x3 = (x2 x + 2^11) >> 12, and in units of 2^-13:
///   spline (Catmull-Rom), nodes cell - 1 .. cell + 2:
///     C = (-x3 + 2 x2 - x, 3 x3 - 5 x2 + 2^13, -3 x3 + 4 x2 + x, x3 - x2)
///     D = (-3 x2 + 4 x - 2^12, 9 x2 - 10 x, -9 x2 + 8 x + 2^12, 3 x2 - 2 x)
///   linear, nodes cell, cell + 1: C = (2 (2^12 - x), 2 x, 0, 0), D = (-2^13, 2^13, 0, 0)
/// Golden extrapolates a node beyond the grid, n(-1) = 2 n(0) - n(1) and n(cells + 1) =
/// 2 n(cells) - n(cells - 1), and weights it. That is linear in the nodes, so the same sum
/// comes from weighting only nodes inside the grid with the outside weight moved onto them:
///   cell = 0 (node -1 outside):             w1 += 2 w0, w2 -= w0, w0 = 0
///   cell = cells - 1 (node cells + 1 outside): w2 += 2 w3, w1 -= w3, w3 = 0
/// (with one cell both, and node cells - 1 is node 0: the same two lines). Every sum stays
/// exact, so the unit's result is golden's bit for bit, and a sample never reads a node
/// outside the grid: 16 reads of in-grid nodes (or 4, linear), some weighted zero.
/// Folded weights, over every x and fold: |C| <= 2^13, |D| <= 11382 (WW = 16 bits signed);
/// sum |C| <= 10240, sum |D| <= 24576 (what bounds the products and sums of tmu_tau).
module tmu_tau_weights #(
  localparam int unsigned WW = 16
) (
  input  logic [12:0]          x_i,
  input  logic [12:0]          x2_i,
  input  logic [3:0]           cell_i,
  /// 1..16
  input  logic [4:0]           cells_i,
  input  tmu_pkg::tau_interp_t interp_i,
  /// The stencil's first node index: cell - 1 (spline) or cell (linear), -1 .. 15.
  output logic signed [5:0]    first_o,
  /// Weight k of the node first + k at [k*WW +: WW], signed.
  output logic [4*WW-1:0]      c_o,
  output logic [4*WW-1:0]      d_o
);

  logic [25:0]        product;
  logic signed [WW:0] x, x2, x3;  // 0 .. 2^12, signed for the sums below
  logic signed [WW:0] c [4];
  logic signed [WW:0] d [4];
  logic               lo_out, hi_out;

  // The integer constants, at the sums' width (lint-clean products).
  typedef logic signed [WW:0] w_t;
  localparam w_t K2 = 2, K3 = 3, K4 = 4, K5 = 5, K8 = 8, K9 = 9, K10 = 10;
  localparam w_t Half = 4096, One = 8192;

  assign product = 26'(x2_i) * 26'(x_i);
  assign x   = (WW + 1)'(x_i);
  assign x2  = (WW + 1)'(x2_i);
  assign x3  = (WW + 1)'((product + 26'd2048) >> 12);

  assign lo_out = cell_i == 4'd0;
  assign hi_out = 5'(cell_i) == cells_i - 5'd1;

  always_comb begin
    if (interp_i == 1'b1) begin
      c[0] = -x3 + K2 * x2 - x;
      c[1] = K3 * x3 - K5 * x2 + One;
      c[2] = -K3 * x3 + K4 * x2 + x;
      c[3] = x3 - x2;
      d[0] = -K3 * x2 + K4 * x - Half;
      d[1] = K9 * x2 - K10 * x;
      d[2] = -K9 * x2 + K8 * x + Half;
      d[3] = K3 * x2 - K2 * x;
      if (lo_out) begin
        c[1] = c[1] + K2 * c[0];
        c[2] = c[2] - c[0];
        c[0] = '0;
        d[1] = d[1] + K2 * d[0];
        d[2] = d[2] - d[0];
        d[0] = '0;
      end
      if (hi_out) begin
        c[2] = c[2] + K2 * c[3];
        c[1] = c[1] - c[3];
        c[3] = '0;
        d[2] = d[2] + K2 * d[3];
        d[1] = d[1] - d[3];
        d[3] = '0;
      end
      first_o = 6'(cell_i) - 6'sd1;
    end else begin
      c[0] = K2 * (Half - x);
      c[1] = K2 * x;
      c[2] = '0;
      c[3] = '0;
      d[0] = -One;
      d[1] = One;
      d[2] = '0;
      d[3] = '0;
      first_o = 6'(cell_i);
    end
  end

  // The weights fit WW bits (above); the extra bit only carried the intermediate sums.
  logic unused_top;
  always_comb begin
    unused_top = 1'b0;
    for (int k = 0; k < 4; k++) begin
      c_o[k*WW +: WW] = WW'(c[k]);
      d_o[k*WW +: WW] = WW'(d[k]);
      unused_top = unused_top ^ c[k][WW] ^ d[k][WW];
    end
  end

endmodule
