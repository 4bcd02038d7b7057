/// The procedural noise unit (002 §4.1; golden perlin::noise in golden/perlin/noise.hpp, the
/// specification): value noise on the integer lattice at solid coordinates (u, v, w). One
/// sample per clock.
///
///   split   each SQ12.12 coordinate into the lattice index i = floor(x) mod 2^12 (raw bits
///           23:12) and the fraction; only its top S bits matter (they index the fade table),
///           so F (FracBits) constrains S <= F and changes nothing else
///   fade    c = FADE[top S bits of the fraction], UQ1.B, from a table of 2^S entries built at
///           elaboration: ((3k^2 2^S - 2k^3) 2^B + 2^(3S-1)) >> 3S (round half up, exact)
///   hash    the eight corners (iu + du, iv + dv, iw + dw), d in {0, 1}:
///           h = T((T((T((T(x1) + x2) mod 2^12) + x3) mod 2^12) + x3) mod 2^12), the last
///           coordinate added twice; T the 12 x 12 xor table (bit j = parity of x & row j,
///           tmu_pkg::NoiseXorRow0..11). The corners share their prefixes: 2 + 4 + 8 + 8 T's.
///           The lattice value is h's top 8 bits, signed, extended by X zero fraction bits
///   lerp    f(a, b, c) = a + ((c (b - a) + 2^(B-1)) >>> B), four along u, two along v, one
///           along w (golden's order); it stays between a and b, so P is SQ0.(7 + X) in [-1, 1)
///
/// Pipeline. Each stage is a register with a valid bit; the whole pipeline advances when the
/// output register is empty or being taken, and stalls otherwise:
///   S1 split     the three fade weights; T(iu), T(iu + 1); iv, iw
///   S2 hash v    T(h + iv + dv), four prefixes
///   S3 hash w    T(h + iw + dw), the eight corners
///   S4 hash w'   T(h + iw + dw) again: the eight lattice values
///   S5 lerp u    four lerps with c_u
///   S6 lerp v    two lerps with c_v
///   S7 lerp w    one lerp with c_w: out_p_o
/// A coordinate accepted at an edge is on the output 6 edges later when nothing stalls
/// (latency 7 cycles).
///
/// Example (defaults): (u, v, w) = (0, 0, 0), a lattice point: every fraction is 0, every
/// fade weight FADE[0] = 0, so P is the corner (0, 0, 0)'s value: h = T(T(T(T(0) + 0) + 0) +
/// 0) = 0, the value 0, P = 0. At (0.5, 0, 0) = (0x000800, 0, 0): c_u = FADE[128] = 128
/// (sm(1/2) = 1/2), P = round((R(0,0,0) + R(1,0,0)) 16 / 2).
module tmu_noise #(
  /// F: coordinate fraction bits the unit keeps, 1..12.
  parameter int unsigned FracBits      = 8,
  /// S: fade-table index bits, 1..F.
  parameter int unsigned FadeIndexBits = 8,
  /// B: fade-table entry fraction bits (UQ1.B), 2..12.
  parameter int unsigned FadeBits      = 8,
  /// X: lerp fraction bits below the lattice values' 7, 0..8; the port is tmu_pkg's
  /// noise_value_t at X = 4.
  parameter int unsigned LerpExtraBits = 4,
  /// Bits of P (derived): SQ0.(7 + X).
  localparam int unsigned PW = 8 + LerpExtraBits
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,

  /// The solid coordinates, SQ12.12.
  input  logic                  in_valid_i,
  output logic                  in_ready_o,
  input  tmu_pkg::solid_coord_t in_u_i,
  input  tmu_pkg::solid_coord_t in_v_i,
  input  tmu_pkg::solid_coord_t in_w_i,

  /// The noise P, SQ0.(7 + X) raw.
  output logic                  out_valid_o,
  input  logic                  out_ready_i,
  output logic [PW-1:0]         out_p_o
);

  localparam int unsigned F  = FracBits;
  localparam int unsigned S  = FadeIndexBits;
  localparam int unsigned B  = FadeBits;
  localparam int unsigned X  = LerpExtraBits;
  localparam int unsigned CW = tmu_pkg::SolidCoordW;     // 24
  localparam int unsigned CF = tmu_pkg::SolidCoordFrac;  // 12
  localparam int unsigned LW = 12;                       // lattice index and hash bits
  localparam int unsigned VW = 8;                        // lattice value bits, SQ0.7
  localparam int unsigned FW = B + 1;                    // a fade weight, 0 .. 2^B
  localparam int unsigned NumStages = 7;

  if (F < 1 || F > 12 || S < 1 || S > F || B < 2 || B > 12 || X > 8) begin : gen_check
    $error("tmu_noise: FracBits 1..12, FadeIndexBits 1..FracBits, FadeBits 2..12, LerpExtraBits 0..8");
  end
  if (CW != 24 || CF != 12 || (X == 4 && PW != tmu_pkg::NoiseValueW)) begin : gen_check_formats
    $error("tmu_noise: built for SQ12.12 coordinates and the SQ0.11 NoiseValue at X = 4");
  end

  // ---- Constants ------------------------------------------------------------------------------

  // T's rows, row j at [j * LW +: LW].
  localparam logic [LW*LW-1:0] XorRows = {
    LW'(tmu_pkg::NoiseXorRow11), LW'(tmu_pkg::NoiseXorRow10), LW'(tmu_pkg::NoiseXorRow9),
    LW'(tmu_pkg::NoiseXorRow8),  LW'(tmu_pkg::NoiseXorRow7),  LW'(tmu_pkg::NoiseXorRow6),
    LW'(tmu_pkg::NoiseXorRow5),  LW'(tmu_pkg::NoiseXorRow4),  LW'(tmu_pkg::NoiseXorRow3),
    LW'(tmu_pkg::NoiseXorRow2),  LW'(tmu_pkg::NoiseXorRow1),  LW'(tmu_pkg::NoiseXorRow0)};

  // The scramble T: bit j is the parity of x & row j.
  function automatic logic [LW-1:0] scramble(input logic [LW-1:0] x);
    for (int j = 0; j < LW; j++) scramble[j] = ^(x & XorRows[j*LW +: LW]);
  endfunction

  // golden fade_entry: round(sm(k / 2^S) 2^B) half up, in integers (at most 2^50: 64 bits).
  function automatic logic [FW-1:0] fade_entry(input int unsigned k);
    logic [63:0] kk, num;
    kk  = 64'(k);
    num = (((64'(3) * kk * kk) << S) - 64'(2) * kk * kk * kk) << B;
    fade_entry = FW'((num + (64'(1) << (3 * S - 1))) >> (3 * S));
  endfunction

  // The fade table, entry k at [k * FW +: FW] (two loops of at most 64 and 64 entries).
  localparam int unsigned LoBits = S > 6 ? 6 : S;
  logic [(1 << S)*FW-1:0] fade_table;
  for (genvar hi = 0; hi < (1 << (S - LoBits)); hi++) begin : gen_fade_hi
    for (genvar lo = 0; lo < (1 << LoBits); lo++) begin : gen_fade_lo
      localparam int unsigned K = (hi << LoBits) + lo;
      localparam logic [FW-1:0] Entry = fade_entry(K);
      assign fade_table[K*FW +: FW] = Entry;
    end
  end

  // f(a, b, c) = a + ((c (b - a) + 2^(B-1)) >>> B) on PW-bit two's complement values. The
  // result lies between a and b, so its low PW bits are a's plus the step's.
  function automatic logic [PW-1:0] lerp(input logic [PW-1:0] a, input logic [PW-1:0] b,
                                         input logic [FW-1:0] c);
    logic signed [PW:0]      diff;     // b - a, exact
    logic signed [PW+FW+1:0] product;  // c (b - a) + 2^(B-1), exact
    logic [PW-1:0]           step;     // its low PW bits after the shift
    diff    = $signed({b[PW-1], b} - {a[PW-1], a});
    product = $signed({1'b0, c}) * diff + $signed((PW + FW + 2)'(1) << (B - 1));
    step    = PW'(product >>> B);
    lerp    = a + step;
  endfunction

  // ---- Pipeline control: tmu_pipe_ctrl ------------------------------------------------------

  // valid[j]: stage j holds a sample; load[j]: stage j takes stage j - 1's at this edge.
  // The stages load on load[j]; of the valids only an assertion reads one (valid[1]).
  // verilator lint_off UNUSEDSIGNAL
  logic [NumStages:1] valid, load;
  // verilator lint_on UNUSEDSIGNAL

  tmu_pipe_ctrl #(.NumStages(NumStages)) u_pipe_ctrl (.clk_i, .rst_ni, .in_valid_i, .in_ready_o,
    .out_valid_o, .out_ready_i, .valid_o(valid), .load_o(load));

  // The fade weights travel with the sample until their lerp: u to S4, v to S5, w to S6.
  logic [FW-1:0] s1_cu_q, s2_cu_q, s3_cu_q, s4_cu_q;
  logic [FW-1:0] s1_cv_q, s2_cv_q, s3_cv_q, s4_cv_q, s5_cv_q;
  logic [FW-1:0] s1_cw_q, s2_cw_q, s3_cw_q, s4_cw_q, s5_cw_q, s6_cw_q;

  // ---- -> S1: split, fade, T(iu + du) ---------------------------------------------------------

  logic [LW-1:0] iu, iv, iw;
  logic [S-1:0]  ku, kv, kw;

  assign iu = in_u_i[CW-1:CF];
  assign iv = in_v_i[CW-1:CF];
  assign iw = in_w_i[CW-1:CF];
  assign ku = in_u_i[CF-1:CF-S];
  assign kv = in_v_i[CF-1:CF-S];
  assign kw = in_w_i[CF-1:CF-S];

  // The fraction bits below the fade index change nothing (the golden split keeps F bits and
  // drops F - S of them again).
  if (S < CF) begin : gen_unused_frac
    logic unused_frac;
    assign unused_frac = ^{in_u_i[CF-S-1:0], in_v_i[CF-S-1:0], in_w_i[CF-S-1:0]};
  end

  // Flat vectors, element n at [n * W +: W] (Yosys 0.23 has no packed arrays of vectors).
  logic [2*LW-1:0] s1_h_q;  // T(iu + du)
  logic [LW-1:0] s1_iv_q, s1_iw_q;

  // ---- S1 -> S2: T(h + iv + dv), index du + 2 dv ----------------------------------------------

  logic [4*LW-1:0] s2_h_q;
  logic [LW-1:0] s2_iw_q;

  // ---- S2 -> S3 -> S4: T(h + iw + dw) twice, index du + 2 dv + 4 dw ---------------------------

  logic [8*LW-1:0] s3_h_q;
  logic [LW-1:0] s3_iw_q;
  logic [8*VW-1:0] s4_value_q;  // the lattice values, SQ0.7

  // ---- S4 -> S5 -> S6 -> S7: the lerps ----------------------------------------------------------

  logic [4*PW-1:0] s5_x_q;  // along u, index dv + 2 dw
  logic [2*PW-1:0] s6_y_q;  // along v, index dw
  logic [PW-1:0] s7_p_q;

  assign out_p_o = s7_p_q;

  // ---- Data registers: only read while their stage is valid, no reset --------------------------

  for (genvar du = 0; du < 2; du++) begin : gen_s1
    always_ff @(posedge clk_i) begin
      if (load[1]) s1_h_q[du*LW +: LW] <= scramble(iu + LW'(du));
    end
  end

  for (genvar n = 0; n < 4; n++) begin : gen_s2  // n = du + 2 dv
    always_ff @(posedge clk_i) begin
      if (load[2]) s2_h_q[n*LW +: LW] <= scramble(s1_h_q[(n%2)*LW +: LW] + s1_iv_q + LW'(n / 2));
    end
  end

  for (genvar n = 0; n < 8; n++) begin : gen_s3_s4  // n = du + 2 dv + 4 dw
    logic [LW-1:0] h4;
    assign h4 = scramble(s3_h_q[n*LW +: LW] + s3_iw_q + LW'(n / 4));
    always_ff @(posedge clk_i) begin
      if (load[3]) s3_h_q[n*LW +: LW] <= scramble(s2_h_q[(n%4)*LW +: LW] + s2_iw_q + LW'(n / 4));
      if (load[4]) s4_value_q[n*VW +: VW] <= h4[LW-1:LW-VW];
    end
    if (VW < LW) begin : gen_unused_hash
      logic unused_hash;
      assign unused_hash = ^h4[LW-VW-1:0];
    end
  end

  for (genvar n = 0; n < 4; n++) begin : gen_s5  // n = dv + 2 dw: corners du = 0, 1
    logic [PW-1:0] a, b;
    assign a = PW'(s4_value_q[(2*n)*VW +: VW]) << X;  // SQ0.7 to SQ0.(7 + X)
    assign b = PW'(s4_value_q[(2*n+1)*VW +: VW]) << X;
    always_ff @(posedge clk_i) begin
      if (load[5]) s5_x_q[n*PW +: PW] <= lerp(a, b, s4_cu_q);
    end
  end

  for (genvar n = 0; n < 2; n++) begin : gen_s6  // n = dw: dv = 0, 1
    always_ff @(posedge clk_i) begin
      if (load[6]) s6_y_q[n*PW +: PW] <= lerp(s5_x_q[(2*n)*PW +: PW], s5_x_q[(2*n+1)*PW +: PW], s5_cv_q);
    end
  end

  always_ff @(posedge clk_i) begin
    if (load[1]) begin
      s1_cu_q <= fade_table[32'(ku)*FW +: FW];
      s1_cv_q <= fade_table[32'(kv)*FW +: FW];
      s1_cw_q <= fade_table[32'(kw)*FW +: FW];
      s1_iv_q <= iv;
      s1_iw_q <= iw;
    end
    if (load[2]) begin
      s2_cu_q <= s1_cu_q;
      s2_cv_q <= s1_cv_q;
      s2_cw_q <= s1_cw_q;
      s2_iw_q <= s1_iw_q;
    end
    if (load[3]) begin
      s3_cu_q <= s2_cu_q;
      s3_cv_q <= s2_cv_q;
      s3_cw_q <= s2_cw_q;
      s3_iw_q <= s2_iw_q;
    end
    if (load[4]) begin
      s4_cu_q <= s3_cu_q;
      s4_cv_q <= s3_cv_q;
      s4_cw_q <= s3_cw_q;
    end
    if (load[5]) begin
      s5_cv_q <= s4_cv_q;
      s5_cw_q <= s4_cw_q;
    end
    if (load[6]) s6_cw_q <= s5_cw_q;
    if (load[7]) s7_p_q <= lerp(s6_y_q[0 +: PW], s6_y_q[PW +: PW], s6_cw_q);
  end

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // The fade weights are in 0 .. 2^B (UQ1.B).
  a_fade_range: assert property (@(posedge clk_i) disable iff (!rst_ni)
      valid[1] |-> (s1_cu_q <= FW'(1 << B) && s1_cv_q <= FW'(1 << B) && s1_cw_q <= FW'(1 << B)));
`endif

endmodule
