/// The footprint marcher (000 §10, Fig. 13; golden footprint::probe in
/// golden/footprint/footprint.hpp): the N = 2^k probes of a fragment, one per clock, along its
/// marching direction d (r1, or r2 when longer), centred on p = (u, v).
///
/// Probe i (0 .. N-1) is n = 2i - (N - 1) half-steps of d / N from the centre:
///   p_i = (p 2^(k+1) + n d + 2^k) >> (k + 1)     (exact, rounded half up to the port's bits)
/// The numerator is kept exactly and advanced by 2 d per probe (no multiplier): it starts at
/// p 2^(k+1) + 2^k - (N - 1) d and fits NumW = 30 bits signed (|p| <= 2^23, |d| <= 2^23,
/// k <= 4: |num| < 2^28 + 15 2^23 + 16 < 2^29). The shifted coordinate can leave the port's
/// range (SQ16.8): on a wrap or mirror axis it wraps modulo 2^16 texels (its low 24 bits: a
/// multiple of every texture period, the same sample), on a clamp or border axis it
/// saturates (beyond the edge either way: the same sample).
///
/// Timing: a plan is taken when the marcher is idle or sends its last probe in that cycle,
/// and the average's k FIFO has room (frag_push_o pushes k with it); its first probe is on
/// probe_* the next cycle, then one per clock while probe_ready_i is high. The probe outputs
/// come from registers through the shift and the saturation only.
///
/// Example: p = 10.0 (raw 0xA00), d = 3.0 (raw 0x300), k = 2: num starts at 0xA00 * 8 + 4 -
/// 3 * 0x300 = 0x4704, steps 0x600: probes 0x8E0, 0x9A0, 0xA60, 0xB20 (8.875, 9.625, 10.375,
/// 11.125 texels: p + (-3, -1, 1, 3) d / 8).
module tmu_footprint_march (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  /// Per axis: the probe coordinate saturates (clamp, border colour) or wraps (wrap, mirror).
  input  logic                 cfg_saturate_u_i,
  input  logic                 cfg_saturate_v_i,

  /// The setup's plan of a fragment.
  input  logic                 plan_valid_i,
  output logic                 plan_ready_o,
  input  tmu_pkg::tex_coord_t  plan_u_i,
  input  tmu_pkg::tex_coord_t  plan_v_i,
  input  tmu_pkg::tex_deriv_t  plan_du_i,
  input  tmu_pkg::tex_deriv_t  plan_dv_i,
  input  tmu_pkg::rgba8888_t   plan_shade_i,
  input  tmu_pkg::probe_log2_t plan_log2_n_i,
  input  tmu_pkg::lod_t        plan_lambda_i,

  /// The fragment's k, pushed into the average's FIFO as its plan is taken (not while full).
  output logic                 frag_push_o,
  output tmu_pkg::probe_log2_t frag_log2_n_o,
  input  logic                 frag_full_i,

  /// Probes: requests of the trilinear unit.
  output logic                 probe_valid_o,
  input  logic                 probe_ready_i,
  output tmu_pkg::tex_coord_t  probe_u_o,
  output tmu_pkg::tex_coord_t  probe_v_o,
  output tmu_pkg::lod_t        probe_lambda_o,
  output tmu_pkg::rgba8888_t   probe_shade_o,

  /// A fragment is being marched.
  output logic                 busy_o
);

  localparam int unsigned PW   = tmu_pkg::TexCoordW;     // 24
  localparam int unsigned DW   = tmu_pkg::TexDerivW;     // 24
  localparam int unsigned KMax = tmu_pkg::MaxProbeLog2;  // 4
  localparam int unsigned NumW = PW + KMax + 2;          // 30
  localparam int unsigned CntW = KMax;                   // probes left - 1: 0 .. 15
  localparam logic signed [NumW-1:0] PortMax = NumW'((1 << (PW - 1)) - 1);
  localparam logic signed [NumW-1:0] PortMin = -NumW'(1 << (PW - 1));

  if (PW != DW || KMax != 4 || tmu_pkg::ProbeLog2W != 3) begin : gen_check
    $error("tmu_footprint_march: built for equal coordinate and derivative formats, 16 probes");
  end

  logic                 active_q, last, fire, load;
  logic signed [NumW-1:0] num_u_q, num_v_q, step_u_q, step_v_q;
  logic [CntW-1:0]      left_q;
  tmu_pkg::probe_log2_t k_q;
  tmu_pkg::lod_t        lambda_q;
  tmu_pkg::rgba8888_t   shade_q;

  assign fire         = active_q && probe_ready_i;
  assign last         = left_q == '0;
  assign plan_ready_o = (!active_q || (fire && last)) && !frag_full_i;
  assign load         = plan_valid_i && plan_ready_o;
  assign frag_push_o   = load;
  assign frag_log2_n_o = plan_log2_n_i;
  assign busy_o       = active_q;

  // The first numerator: p 2^(k+1) + 2^k - (N - 1) d = (p << (k+1)) + (1 << k) - (d << k) + d.
  logic signed [NumW-1:0] p_u, p_v, d_u, d_v, num0_u, num0_v;
  assign p_u    = NumW'(plan_u_i);  // sign-extended
  assign p_v    = NumW'(plan_v_i);
  assign d_u    = NumW'(plan_du_i);
  assign d_v    = NumW'(plan_dv_i);
  assign num0_u = (p_u <<< (plan_log2_n_i + 3'd1)) + (NumW'(1) << plan_log2_n_i) -
                  (d_u <<< plan_log2_n_i) + d_u;
  assign num0_v = (p_v <<< (plan_log2_n_i + 3'd1)) + (NumW'(1) << plan_log2_n_i) -
                  (d_v <<< plan_log2_n_i) + d_v;

  // The probe: the numerator >> (k + 1), then wrapped (its low bits) or saturated.
  logic signed [NumW-1:0] coord_u, coord_v;
  assign coord_u = num_u_q >>> (k_q + 3'd1);
  assign coord_v = num_v_q >>> (k_q + 3'd1);

  function automatic tmu_pkg::tex_coord_t to_port(input logic signed [NumW-1:0] c,
                                                  input logic saturate);
    if (saturate && c > PortMax) begin
      to_port = PW'(PortMax);
    end else if (saturate && c < PortMin) begin
      to_port = PW'(PortMin);
    end else begin
      to_port = PW'(c);  // in range, or wrapped modulo 2^16 texels
    end
  endfunction

  assign probe_valid_o  = active_q;
  assign probe_u_o      = to_port(coord_u, cfg_saturate_u_i);
  assign probe_v_o      = to_port(coord_v, cfg_saturate_v_i);
  assign probe_lambda_o = lambda_q;
  assign probe_shade_o  = shade_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      active_q <= 1'b0;
    end else begin
      active_q <= load || (active_q && !(fire && last));
    end
  end

  // Data registers are read only while a fragment is active: no reset.
  always_ff @(posedge clk_i) begin
    if (load) begin
      num_u_q  <= num0_u;
      num_v_q  <= num0_v;
      step_u_q <= d_u <<< 1;
      step_v_q <= d_v <<< 1;
      left_q   <= CntW'((1 << plan_log2_n_i) - 1);
      k_q      <= plan_log2_n_i;
      lambda_q <= plan_lambda_i;
      shade_q  <= plan_shade_i;
    end else if (fire) begin
      num_u_q  <= num_u_q + step_u_q;
      num_v_q  <= num_v_q + step_v_q;
      left_q   <= left_q - CntW'(1);
    end
  end

`ifndef SYNTHESIS
  // The plan and probe channels' ready/valid rules are checked at the setup's plan port and
  // the trilinear unit's req port (their u_plan_check, u_req_check: tmu_stream_check).
  // k is 0..4.
  property p_k_in_range;
    @(posedge clk_i) disable iff (!rst_ni) load |-> plan_log2_n_i <= 3'(KMax);
  endproperty
  a_k_in_range: assert property (p_k_in_range);
`endif

endmodule
