/// The fractal sums of four octaves, pipelined (002 §4.1.1; golden perlin::fractal_sums in
/// golden/perlin/noise.hpp, the specification): four noise units side by side, one per
/// octave, one sample per clock. The area-for-speed counterpart of tmu_fractal_shared.
///
///   octave i = 0..3 reads the noise at 2^i (u, v, w): the raw SQ12.12 coordinates shifted left
///   by i and wrapped to 24 bits. Golden multiplies in 64 bits, but the noise reads only bits
///   23:12 (the lattice index mod 2^12) and 11:12-S (the fade index) of a coordinate, and the
///   low 24 bits of x 2^i are those of the wrapped shift: the same noise.
///   fractal sum  = sum_i 2^(3-i) P_i        turbulence = sum_i 2^(3-i) |P_i|
///   (SQ2.(10 + X) raw: P_i is SQ0.(7 + X), so 2^-i P_i is P_i shifted left by 3 - i.) |P_i|
///   of P_i = -1.0 is +1.0, one bit wider than P: the magnitude is PW + 1 bits unsigned.
///
/// Pipeline: the four tmu_noise share the input handshake and the output stall, so they run
/// in lockstep (S1-S7); S8 adds the four octaves into out_sum_o and out_turbulence_o. A
/// sample accepted at an edge is on the output 7 edges later when nothing stalls (latency 8
/// cycles).
///
/// Example (defaults): (u, v, w) = (0, 0, 0): every octave is at the lattice point 0, where
/// the lattice value is 0: both sums are 0. At a lattice point whose value is -1.0 in every
/// octave the turbulence would be 15/8 = 30720 raw (the largest), the fractal sum -30720.
module tmu_fractal_pipelined #(
  /// The noise units' widths F, S, B, X (tmu_noise); the ports are tmu_pkg's
  /// fractal_value_t at X = 4.
  parameter int unsigned FracBits      = 8,
  parameter int unsigned FadeIndexBits = 8,
  parameter int unsigned FadeBits      = 8,
  parameter int unsigned LerpExtraBits = 4,
  /// Bits of the sums (derived): SQ2.(10 + X).
  localparam int unsigned SW = 12 + LerpExtraBits
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,

  /// The solid coordinates, SQ12.12.
  input  logic                  in_valid_i,
  output logic                  in_ready_o,
  input  tmu_pkg::solid_coord_t in_u_i,
  input  tmu_pkg::solid_coord_t in_v_i,
  input  tmu_pkg::solid_coord_t in_w_i,

  /// The fractal sum and the turbulence, SQ2.(10 + X) raw.
  output logic                  out_valid_o,
  input  logic                  out_ready_i,
  output logic [SW-1:0]         out_sum_o,
  output logic [SW-1:0]         out_turbulence_o
);

  localparam int unsigned PW      = 8 + LerpExtraBits;  // P, SQ0.(7 + X)
  localparam int unsigned Octaves = 4;

  if (LerpExtraBits == 4 && SW != tmu_pkg::FractalValueW) begin : gen_check_formats
    $error("tmu_fractal_pipelined: built for the SQ2.14 FractalValue at X = 4");
  end

  // ---- S1-S7: the noise of each octave ------------------------------------------------------

  logic                        advance;  // S8 empty or being taken
  logic [Octaves-1:0]          noise_in_ready, noise_valid;
  // P_i at [i * PW +: PW], |P_i| (unsigned) at [i * (PW + 1) +: PW + 1] (flat: Yosys 0.23 has
  // no packed arrays of vectors).
  logic [Octaves*PW-1:0]       p;
  logic [Octaves*(PW+1)-1:0]   mag;

  for (genvar i = 0; i < Octaves; i++) begin : gen_octave
    localparam int unsigned Shift = i;  // octave i at 2^i (u, v, w)
    tmu_pkg::solid_coord_t u, v, w;
    assign u = in_u_i << Shift;
    assign v = in_v_i << Shift;
    assign w = in_w_i << Shift;

    tmu_noise #(
      .FracBits      (FracBits),
      .FadeIndexBits (FadeIndexBits),
      .FadeBits      (FadeBits),
      .LerpExtraBits (LerpExtraBits)
    ) u_noise (
      .clk_i       (clk_i),
      .rst_ni      (rst_ni),
      .in_valid_i  (in_valid_i),
      .in_ready_o  (noise_in_ready[i]),
      .in_u_i      (u),
      .in_v_i      (v),
      .in_w_i      (w),
      .out_valid_o (noise_valid[i]),
      .out_ready_i (advance),
      .out_p_o     (p[i*PW +: PW])
    );

    // -P in PW bits: -(-2^(PW-1)) wraps to 2^(PW-1), which read unsigned is |P|.
    logic [PW-1:0] pi, neg;
    assign pi  = p[i*PW +: PW];
    assign neg = -pi;
    assign mag[i*(PW+1) +: PW+1] = pi[PW-1] ? {1'b0, neg} : {1'b0, pi};
  end

  // The units run in lockstep: octave 0's handshake stands for all four.
  assign in_ready_o = noise_in_ready[0];
  logic unused_lockstep;
  assign unused_lockstep = ^{noise_in_ready[Octaves-1:1], noise_valid[Octaves-1:1]};

  // ---- S7 -> S8: the sums -----------------------------------------------------------------------

  logic [SW-1:0] sum, turbulence;
  always_comb begin
    sum        = '0;
    turbulence = '0;
    for (int i = 0; i < Octaves; i++) begin
      sum        = sum + ({{(SW - PW){p[i*PW+PW-1]}}, p[i*PW +: PW]} << (Octaves - 1 - i));
      turbulence = turbulence + (SW'(mag[i*(PW+1) +: PW+1]) << (Octaves - 1 - i));
    end
  end

  logic          s8_valid_q;
  logic [SW-1:0] s8_sum_q, s8_turbulence_q;

  assign advance          = !s8_valid_q || out_ready_i;
  assign out_valid_o      = s8_valid_q;
  assign out_sum_o        = s8_sum_q;
  assign out_turbulence_o = s8_turbulence_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s8_valid_q <= 1'b0;
    end else if (advance) begin
      s8_valid_q <= noise_valid[0];
    end
  end

  // Data registers: only read while valid, no reset.
  always_ff @(posedge clk_i) begin
    if (advance && noise_valid[0]) begin
      s8_sum_q        <= sum;
      s8_turbulence_q <= turbulence;
    end
  end

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // The four units stay in lockstep.
  a_lockstep: assert property (@(posedge clk_i) disable iff (!rst_ni)
      noise_in_ready == {Octaves{noise_in_ready[0]}} && noise_valid == {Octaves{noise_valid[0]}});
  // The turbulence is at most 15/8 (the sum of 2^-i over four octaves of |P| <= 1).
  a_turbulence_range: assert property (@(posedge clk_i) disable iff (!rst_ni)
      out_valid_o |-> out_turbulence_o <= SW'(15 << (PW - 1)));
`endif

endmodule
