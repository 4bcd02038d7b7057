/// The normal encoder (001 §4.1, eq. 12-16, Fig. 3; golden deflect::NormalEncoder in
/// golden/deflect/normal_encoder.hpp, the specification): an interpolated, unnormalised
/// Cartesian normal N = (x, y, z) to its angles (phi_N, theta_N) on the sphere grid, without
/// square roots or trigonometry. One normal per clock.
///
///   signs sx, sy, sz; magnitudes a, b, c; squares X = a^2, Y = b^2, Z = c^2, H = X + Z
///   phi:   t = min(X, Z) / max(X, Z), swapped when X > Z  (tan^2 from the nearer axis)
///   theta: t = min(Y, H) / max(Y, H), swapped when Y > H
///   k = ANGLE[t] steps (tmu_normal_angle_lut), 0 for t = 0 (exact axes and planes); Q - k
///   when swapped (Q = 2^(PhiBits-2))
///   phi_N = the first-octant k_phi moved to the quadrant of sx, sz (golden expand_phi)
///   theta_N = (sy, min(k_theta, Q - 1)), zero always +0
/// Equal squares do not swap. The zero normal gives (0, +0); a normal on an octant boundary
/// takes the non-negative side of its zero component.
///
/// Pipeline (the paper duplicates the angle table: phi and theta each have their divider and
/// table, side by side). Each stage is a register with a valid bit; the whole pipeline
/// advances when the output register is empty or being taken, and stalls otherwise (one
/// normal per clock while the output is taken):
///   S1 input     signs and magnitudes
///   S2 squares   X, Y, Z (three 16 x 16 products)
///   S3 ratios    H; the swaps; numerator and denominator of both ratios
///   S4-S7        the two dividers' stages A-D (tmu_normal_divider): normalise and seed,
///                2 - d r0, the Newton-Raphson step, the quotient
///   S8 angles    both table reads, the swaps, the octant: out_phi_o, out_theta_o
/// A normal accepted at an edge is on the output 7 edges later when nothing stalls
/// (latency 8 cycles).
///
/// Example (PhiBits 9): N = (0.5, 0, 1.0) = (8192, 0, 16384): X = 2^26, Z = 2^28, phi: no
/// swap, t = 16383 (0.25 truncated: below 2^14, so e = 1, m = 31, index 63), k = 38 steps
/// (atan 0.5 = 26.6 degrees = 37.8 steps of 0.703 degrees); theta: Y = 0 < H, t = 0, k = 0
/// without the table. Output phi 38, theta +0.
module tmu_normal_encoder #(
  /// A: bits of phi (grid 2^A x 2^(A-1)), 6..12; the ports match tmu_pkg at 9.
  parameter int unsigned PhiBits  = 9,
  /// S: index bits of the dividers' reciprocal seed table, 2..12.
  parameter int unsigned SeedBits = 7,
  /// E, M: exponent levels (1..8) and mantissa bits (2..10) of the angle table's index.
  parameter int unsigned LutExp   = 4,
  parameter int unsigned LutMant  = 5
) (
  input  logic                clk_i,
  input  logic                rst_ni,

  /// The normal, SQ2.14 components of any length (zero included).
  input  logic                in_valid_i,
  output logic                in_ready_o,
  input  tmu_pkg::unit_comp_t in_x_i,
  input  tmu_pkg::unit_comp_t in_y_i,
  input  tmu_pkg::unit_comp_t in_z_i,

  /// Its angles: phi (tmu_pkg::sphere_phi_t at A = 9), theta sign and magnitude
  /// (tmu_pkg::sphere_theta_t at A = 9).
  output logic                out_valid_o,
  input  logic                out_ready_i,
  output logic [PhiBits-1:0]  out_phi_o,
  output logic [PhiBits-2:0]  out_theta_o
);

  localparam int unsigned A  = PhiBits;
  localparam int unsigned KW = A - 2;           // a table entry, 0 .. Q/2
  localparam int unsigned LW = A - 1;           // k after the swap, 0 .. Q
  localparam logic [LW-1:0] Q = LW'(1) << (A - 2);
  localparam logic [A-1:0]  Q2 = A'(1) << (A - 1);  // 2Q
  localparam int unsigned NumStages = 8;

  if (A < 6 || A > 12) begin : gen_check
    $error("tmu_normal_encoder: PhiBits 6..12");
  end
  if (tmu_pkg::UnitCompW != 16) begin : gen_check_formats
    $error("tmu_normal_encoder: built for 16-bit components");
  end

  // ---- Pipeline control: tmu_pipe_ctrl ------------------------------------------------------

  // valid[j]: stage j holds a normal; load[j]: stage j takes stage j - 1's at this edge.
  // The stages load on load[j]; nothing here reads their valids.
  // verilator lint_off UNUSEDSIGNAL
  logic [NumStages:1] valid, load;
  // verilator lint_on UNUSEDSIGNAL

  tmu_pipe_ctrl #(.NumStages(NumStages)) u_pipe_ctrl (.clk_i, .rst_ni, .in_valid_i, .in_ready_o,
    .out_valid_o, .out_ready_i, .valid_o(valid), .load_o(load));

  // Signs (x, y, z at bits 0, 1, 2), from S3 on with the swaps (phi, theta at bits 3, 4),
  // travel to S8.
  typedef logic [4:0] flags_t;
  logic [2:0] s1_signs_q, s2_signs_q;
  flags_t     s3_flags_q, s4_flags_q, s5_flags_q, s6_flags_q, s7_flags_q;

  // ---- -> S1: signs and magnitudes ------------------------------------------------------------

  // |-32768| = 32768 fits 16 bits unsigned.
  function automatic logic [15:0] magnitude(input tmu_pkg::unit_comp_t v);
    magnitude = v[15] ? 16'(-v) : 16'(v);
  endfunction

  logic [15:0] s1_a_q, s1_b_q, s1_c_q;

  // ---- S1 -> S2: squares (at most 2^30) -------------------------------------------------------

  logic [30:0] s2_xx_q, s2_yy_q, s2_zz_q;

  // ---- S2 -> S3: H, swaps, operands -----------------------------------------------------------

  logic [31:0] hh;
  logic        swap_phi, swap_theta;
  assign hh         = 32'(s2_xx_q) + 32'(s2_zz_q);
  assign swap_phi   = s2_xx_q > s2_zz_q;
  assign swap_theta = 32'(s2_yy_q) > hh;

  logic [31:0] s3_num_phi_q, s3_den_phi_q, s3_num_theta_q, s3_den_theta_q;

  // ---- S3 -> S7: the dividers -----------------------------------------------------------------

  logic [16:0] t_phi, t_theta;  // UQ1.16, S7

  tmu_normal_divider #(.SeedBits(SeedBits)) u_divider_phi (
    .clk_i  (clk_i),
    .load_i (load[7:4]),
    .num_i  (s3_num_phi_q),
    .den_i  (s3_den_phi_q),
    .t_o    (t_phi)
  );
  tmu_normal_divider #(.SeedBits(SeedBits)) u_divider_theta (
    .clk_i  (clk_i),
    .load_i (load[7:4]),
    .num_i  (s3_num_theta_q),
    .den_i  (s3_den_theta_q),
    .t_o    (t_theta)
  );

  // ---- S7 -> S8: angles -----------------------------------------------------------------------

  logic [KW-1:0] table_phi, table_theta, angle_phi, angle_theta;

  tmu_normal_angle_lut #(.PhiBits(A), .LutExp(LutExp), .LutMant(LutMant)) u_angle_phi (
    .t_i (t_phi),
    .k_o (table_phi)
  );
  tmu_normal_angle_lut #(.PhiBits(A), .LutExp(LutExp), .LutMant(LutMant)) u_angle_theta (
    .t_i (t_theta),
    .k_o (table_theta)
  );

  logic          sx, sy, sz, swap_phi_s7, swap_theta_s7;
  logic [LW-1:0] k_phi, k_theta;
  logic [A-3:0]  theta_mag;
  logic [A-1:0]  phi;

  assign {swap_theta_s7, swap_phi_s7, sz, sy, sx} = s7_flags_q;

  // t = 0 (the normal in a coordinate plane) is 0 steps without the table, whose first bucket
  // does not start at 0: the axes and the planes between them encode exactly.
  assign angle_phi   = t_phi == '0 ? '0 : table_phi;
  assign angle_theta = t_theta == '0 ? '0 : table_theta;
  // Swapped: the angle from the other axis.
  assign k_phi   = swap_phi_s7 ? Q - LW'(angle_phi) : LW'(angle_phi);
  assign k_theta = swap_theta_s7 ? Q - LW'(angle_theta) : LW'(angle_theta);

  // golden expand_phi, modulo 4Q = 2^A: x >= 0: l (z >= 0) or 2Q - l; x < 0: 2Q + l (z < 0)
  // or 4Q - l.
  always_comb begin
    unique case ({sx, sz})
      2'b00:   phi = A'(k_phi);
      2'b01:   phi = Q2 - A'(k_phi);
      2'b11:   phi = Q2 + A'(k_phi);
      default: phi = '0 - A'(k_phi);
    endcase
  end

  // The pole (k = Q) saturates to Q - 1.
  assign theta_mag = k_theta >= Q ? (A - 2)'(Q - 1'b1) : (A - 2)'(k_theta);

  logic [A-1:0] s8_phi_q;
  logic [A-2:0] s8_theta_q;

  assign out_phi_o   = s8_phi_q;
  assign out_theta_o = s8_theta_q;

  // ---- Data registers: only read while their stage is valid, no reset --------------------------

  always_ff @(posedge clk_i) begin
    if (load[1]) begin
      s1_signs_q <= {in_z_i[15], in_y_i[15], in_x_i[15]};
      s1_a_q     <= magnitude(in_x_i);
      s1_b_q     <= magnitude(in_y_i);
      s1_c_q     <= magnitude(in_z_i);
    end
    if (load[2]) begin
      s2_signs_q <= s1_signs_q;
      s2_xx_q    <= 31'(32'(s1_a_q) * 32'(s1_a_q));
      s2_yy_q    <= 31'(32'(s1_b_q) * 32'(s1_b_q));
      s2_zz_q    <= 31'(32'(s1_c_q) * 32'(s1_c_q));
    end
    if (load[3]) begin
      s3_flags_q     <= {swap_theta, swap_phi, s2_signs_q};
      s3_num_phi_q   <= swap_phi ? 32'(s2_zz_q) : 32'(s2_xx_q);
      s3_den_phi_q   <= swap_phi ? 32'(s2_xx_q) : 32'(s2_zz_q);
      s3_num_theta_q <= swap_theta ? hh : 32'(s2_yy_q);
      s3_den_theta_q <= swap_theta ? 32'(s2_yy_q) : hh;
    end
    if (load[4]) s4_flags_q <= s3_flags_q;
    if (load[5]) s5_flags_q <= s4_flags_q;
    if (load[6]) s6_flags_q <= s5_flags_q;
    if (load[7]) s7_flags_q <= s6_flags_q;
    if (load[8]) begin
      s8_phi_q   <= phi;
      s8_theta_q <= {sy && theta_mag != '0, theta_mag};
    end
  end

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // The dividers see the smaller square over the larger.
  a_ratio_at_most_one: assert property (@(posedge clk_i) disable iff (!rst_ni)
      load[4] |-> (s3_num_phi_q <= s3_den_phi_q && s3_num_theta_q <= s3_den_theta_q));
`endif

endmodule
