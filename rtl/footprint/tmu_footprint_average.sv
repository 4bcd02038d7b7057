/// The footprint average (000 §10; golden footprint::average in
/// golden/footprint/footprint.hpp): the per-channel mean of a fragment's N = 2^k probe
/// colours, (sum + N/2) >> k, rounded half up. The sums need 8 + 4 bits for 16 probes.
///
/// The colours arrive in order from the trilinear unit, one per probe, with nothing to say
/// where a fragment ends: the marcher pushes each fragment's k into a FIFO as it starts the
/// fragment (Depth entries; frag_full_o holds the marcher back, never needed when Depth
/// covers the trilinear unit's samples in flight), and the head of the FIFO says how many
/// colours make the current fragment. The last one completes the sums into the output
/// register, pops the FIFO and clears the sums.
///
/// Timing: one colour per clock. The last colour of a fragment is taken when the output
/// register is empty or is being emptied in that cycle (in_ready_o depends on out_ready_i),
/// so fragments of one probe pass at one per clock. The output is valid the cycle after its
/// last colour.
///
/// Example: k = 2, red channels 10, 11, 11, 11: sum 43, (43 + 2) >> 2 = 11.
module tmu_footprint_average #(
  /// Fragments between the marcher and the average (at least 2, a power of two).
  parameter int unsigned Depth = 16
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  /// A fragment's k, in fragment order.
  input  logic                 frag_push_i,
  input  tmu_pkg::probe_log2_t frag_log2_n_i,
  output logic                 frag_full_o,

  /// The probes' colours, in order.
  input  logic                 in_valid_i,
  output logic                 in_ready_o,
  input  tmu_pkg::rgba8888_t   in_rgba_i,

  /// The fragment's colour.
  output logic                 out_valid_o,
  input  logic                 out_ready_i,
  output tmu_pkg::rgba8888_t   out_rgba_o
);

  localparam int unsigned KMax = tmu_pkg::MaxProbeLog2;  // 4
  localparam int unsigned CW   = tmu_pkg::ChannelW;      // 8
  localparam int unsigned SumW = CW + KMax;              // 12
  localparam int unsigned PtrW = $clog2(Depth);

  if (Depth < 2 || (1 << PtrW) != Depth || tmu_pkg::Rgba8888W != 4 * CW) begin : gen_check
    $error("tmu_footprint_average: Depth must be a power of two, at least 2");
  end

  // ---- k FIFO -------------------------------------------------------------------------------

  tmu_pkg::probe_log2_t fifo_q [Depth];
  logic [PtrW-1:0]      wr_ptr_q, rd_ptr_q;
  logic [PtrW:0]        count_q;
  tmu_pkg::probe_log2_t head_k;
  logic                 pop;

  assign frag_full_o = count_q == (PtrW + 1)'(Depth);
  assign head_k      = fifo_q[rd_ptr_q];

  // ---- Sums ---------------------------------------------------------------------------------

  logic [4*SumW-1:0]  sum_q;  // channel c (0 R .. 3 A) at [c * SumW +: SumW]
  logic [KMax-1:0]    count_in_q;  // colours of the current fragment so far
  logic               last, in_fire, out_free;
  logic [4*SumW-1:0]  sum_next;
  tmu_pkg::rgba8888_t mean;

  assign last       = count_in_q == KMax'((1 << head_k) - 1);
  assign out_free   = !out_valid_o || out_ready_i;
  assign in_ready_o = !last || out_free;
  assign in_fire    = in_valid_i && in_ready_o;
  assign pop        = in_fire && last;

  always_comb begin
    for (int c = 0; c < 4; c++) begin
      // Channel c of RGBA8888 is in bits 31 - 8c .. 24 - 8c.
      sum_next[c*SumW +: SumW] = sum_q[c*SumW +: SumW] + SumW'(in_rgba_i[(3 - c)*CW +: CW]);
      // (sum + N/2) >> k; N/2 = 0 for k = 0. At most (16 * 255 + 8) >> 4: 8 bits.
      mean[(3 - c)*CW +: CW] =
          CW'((sum_next[c*SumW +: SumW] + (SumW'(1 << head_k) >> 1)) >> head_k);
    end
  end

  tmu_pkg::rgba8888_t out_rgba_q;
  logic               out_valid_q;

  assign out_valid_o = out_valid_q;
  assign out_rgba_o  = out_rgba_q;

  // ---- Flops --------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_ptr_q    <= '0;
      rd_ptr_q    <= '0;
      count_q     <= '0;
      sum_q       <= '0;
      count_in_q  <= '0;
      out_valid_q <= 1'b0;
    end else begin
      wr_ptr_q    <= wr_ptr_q + PtrW'(frag_push_i);
      rd_ptr_q    <= rd_ptr_q + PtrW'(pop);
      count_q     <= count_q + (PtrW + 1)'(frag_push_i) - (PtrW + 1)'(pop);
      if (in_fire) begin
        sum_q      <= last ? '0 : sum_next;
        count_in_q <= last ? '0 : count_in_q + KMax'(1);
      end
      out_valid_q <= pop || (out_valid_q && !out_ready_i);
    end
  end

  // FIFO entries and the output colour are read only while counted valid: no reset.
  always_ff @(posedge clk_i) begin
    if (frag_push_i) fifo_q[wr_ptr_q] <= frag_log2_n_i;
  end

  always_ff @(posedge clk_i) begin
    if (pop) out_rgba_q <= mean;
  end

`ifndef SYNTHESIS
  // The in and out channels' ready/valid rules are checked at the trilinear unit's and the
  // footprint unit's out ports (their u_out_check: tmu_stream_check).
  // Colours come only for fragments the marcher started.
  property p_colour_expected;
    @(posedge clk_i) disable iff (!rst_ni) in_valid_i |-> count_q != '0;
  endproperty
  a_colour_expected: assert property (p_colour_expected);

  // No push into a full FIFO.
  property p_no_overflow;
    @(posedge clk_i) disable iff (!rst_ni) frag_push_i |-> !frag_full_o;
  endproperty
  a_no_overflow: assert property (p_no_overflow);
`endif

endmodule
