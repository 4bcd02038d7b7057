/// The fractal sums of four octaves on one noise unit (002 §4.1.1: "four cycles are needed to
/// create one fractal value"; golden perlin::fractal_sums in golden/perlin/noise.hpp, the
/// specification): the thesis's design. One tmu_noise computes the four octaves of a sample
/// on four consecutive clocks; a new sample is accepted every 4 clocks. The speed-for-area
/// counterpart of tmu_fractal_pipelined, with the same ports and the same outputs.
///
///   issue       the accepted (u, v, w) is held; octave i = 0..3 sends it shifted left by i
///               (wrapped to 24 bits, as in tmu_fractal_pipelined) to the noise unit, one
///               octave per clock. The next sample is accepted on the clock of octave 3.
///   accumulate  the noise unit returns the octaves in order; Horner's rule doubles the sums
///               before adding each one: ((2 P_0 + P_1) 2 + P_2) 2 + P_3 = sum_i 2^(3-i) P_i,
///               and the same for |P_i| (|-1.0| = +1.0, PW + 1 bits unsigned). Octave 3's sum
///               goes to the output register.
///
/// A sample accepted at an edge has octave 0 in the noise unit at the next edge, octave 3
/// three edges later, and its sums on the output 11 edges after its acceptance when nothing
/// stalls (latency 12 cycles; 4 cycles per sample).
///
/// Example (defaults): (u, v, w) = (0, 0, 0): every octave is at the lattice point 0, where
/// the lattice value is 0: both sums are 0.
module tmu_fractal_shared #(
  /// The noise unit's widths F, S, B, X (tmu_noise); the ports are tmu_pkg's fractal_value_t
  /// at X = 4.
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

  localparam int unsigned PW = 8 + LerpExtraBits;  // P, SQ0.(7 + X)

  if (LerpExtraBits == 4 && SW != tmu_pkg::FractalValueW) begin : gen_check_formats
    $error("tmu_fractal_shared: built for the SQ2.14 FractalValue at X = 4");
  end

  // ---- Issue: one octave per clock ------------------------------------------------------------

  logic                  busy_q;  // a sample is held, octaves oct_q .. 3 still to send
  logic [1:0]            oct_q;
  tmu_pkg::solid_coord_t u_q, v_q, w_q;
  logic                  noise_in_ready, issue, last_issue;
  tmu_pkg::solid_coord_t u, v, w;

  assign issue      = busy_q && noise_in_ready;
  assign last_issue = issue && oct_q == 2'd3;
  assign in_ready_o = !busy_q || last_issue;
  assign u          = u_q << oct_q;  // octave i at 2^i (u, v, w)
  assign v          = v_q << oct_q;
  assign w          = w_q << oct_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q <= 1'b0;
      oct_q  <= 2'd0;
    end else begin
      if (in_ready_o) busy_q <= in_valid_i;
      if (issue) oct_q <= oct_q + 2'd1;  // 3 wraps to 0 for the next sample
    end
  end

  // Data registers: only read while busy, no reset.
  always_ff @(posedge clk_i) begin
    if (in_ready_o && in_valid_i) begin
      u_q <= in_u_i;
      v_q <= in_v_i;
      w_q <= in_w_i;
    end
  end

  // ---- The noise unit ---------------------------------------------------------------------------

  logic          noise_valid, noise_ready;
  logic [PW-1:0] p;

  tmu_noise #(
    .FracBits      (FracBits),
    .FadeIndexBits (FadeIndexBits),
    .FadeBits      (FadeBits),
    .LerpExtraBits (LerpExtraBits)
  ) u_noise (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .in_valid_i  (busy_q),
    .in_ready_o  (noise_in_ready),
    .in_u_i      (u),
    .in_v_i      (v),
    .in_w_i      (w),
    .out_valid_o (noise_valid),
    .out_ready_i (noise_ready),
    .out_p_o     (p)
  );

  // ---- Accumulate: Horner's rule, octave 0 first ------------------------------------------------

  logic          acc_last, take;
  logic [1:0]    acc_oct_q;  // the octave of the next noise output
  logic [SW-1:0] acc_sum_q, acc_turbulence_q, sum, turbulence;
  logic [PW-1:0] neg;
  logic [PW:0]   mag;        // |P|, unsigned
  logic          out_valid_q;
  logic [SW-1:0] out_sum_q, out_turbulence_q;

  // -P in PW bits: -(-2^(PW-1)) wraps to 2^(PW-1), which read unsigned is |P|.
  assign neg = -p;
  assign mag = p[PW-1] ? {1'b0, neg} : {1'b0, p};

  // Octave 0 starts the sums; every later one doubles them first.
  assign sum        = (acc_oct_q == 2'd0 ? '0 : acc_sum_q << 1) + {{(SW - PW){p[PW-1]}}, p};
  assign turbulence = (acc_oct_q == 2'd0 ? '0 : acc_turbulence_q << 1) + SW'(mag);

  // Octaves 0-2 go to the accumulator, octave 3 to the output register when it is free.
  assign acc_last    = acc_oct_q == 2'd3;
  assign noise_ready = !acc_last || !out_valid_q || out_ready_i;
  assign take        = noise_valid && noise_ready;

  assign out_valid_o      = out_valid_q;
  assign out_sum_o        = out_sum_q;
  assign out_turbulence_o = out_turbulence_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      acc_oct_q   <= 2'd0;
      out_valid_q <= 1'b0;
    end else begin
      if (take) acc_oct_q <= acc_oct_q + 2'd1;
      if (take && acc_last) out_valid_q <= 1'b1;
      else if (out_ready_i) out_valid_q <= 1'b0;
    end
  end

  // Data registers: only read while their octave count or valid says so, no reset.
  always_ff @(posedge clk_i) begin
    if (take && !acc_last) begin
      acc_sum_q        <= sum;
      acc_turbulence_q <= turbulence;
    end
    if (take && acc_last) begin
      out_sum_q        <= sum;
      out_turbulence_q <= turbulence;
    end
  end

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // A sample is accepted only with its predecessor's last octave: never on two clocks in a row.
  a_four_clocks: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (in_valid_i && in_ready_o) |=> !(in_valid_i && in_ready_o));
  // The turbulence is at most 15/8 (the sum of 2^-i over four octaves of |P| <= 1).
  a_turbulence_range: assert property (@(posedge clk_i) disable iff (!rst_ni)
      out_valid_o |-> out_turbulence_o <= SW'(15 << (PW - 1)));
`endif

endmodule
