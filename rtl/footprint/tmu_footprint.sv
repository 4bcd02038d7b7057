/// Footprint assembly (000 §10, eq. 19-22, Figs. 12-13), bit-exact with the golden model
/// footprint::sample (golden/footprint/footprint.hpp, the specification): a pixel's elongated
/// footprint in the texture, the parallelogram spanned by r1 = d(u,v)/dx and r2 = d(u,v)/dy,
/// approximated by N = 2^k square trilinear probes marched along its longer side, their
/// colours averaged.
///
///   tmu_footprint_setup    block-floating derivatives, squares and cross product, log2 by
///                          leading one + table, k = log2 N, lambda, the direction (7 stages)
///   tmu_footprint_march    the N probes, one per clock, exact incremental positions, wrapped
///                          or saturated per axis
///   tmu_trilinear          the TEXRAM trilinear unit (000 §2, §5, §6): one sample per probe,
///                          eq. 5 applied per probe with the fragment's shade
///   tmu_footprint_average  per channel (sum + N/2) >> k, with a FIFO of k per fragment
///
/// Latency with page hits and nothing stalled: a fragment accepted at an edge has its first
/// probe on the trilinear unit's request port 8 cycles later (S1..S7, the marcher), its last
/// N - 1 cycles after that; the trilinear unit's results come 12 cycles after their requests,
/// and the average is valid the cycle after the last one: 8 + (N - 1) + 12 + 1 = 20 + N
/// cycles from request to output.
/// Throughput with out_ready_i high: one probe per clock into the trilinear unit while it is
/// ready, so a fragment of N probes takes N clocks of its request port, and back-to-back
/// fragments do not bubble (the setup takes a fragment per clock; the marcher takes the next
/// plan in the cycle its last probe leaves). The trilinear unit takes a probe per clock on
/// 1-plane textures when every access hits the page, one per 4 clocks on 4-plane textures
/// (true colour, CCC), a clock more per page fault; probes with every tap outside (border
/// colour) take one clock.
///
/// Configuration (cfg_*): quasi-static, held for the whole run from before reset; the
/// trilinear unit's as tmu_trilinear says, and the setup's maximum probe count
/// (cfg_log2_max_probes_i, 0..4) and q rule (0 heights, 1 sides).
///
/// The CLUT is the trilinear unit's (a RAM without reset: load before sampling an index or
/// CCC texture). clut_ready_o is high only while no fragment is in the setup or the marcher
/// and the trilinear unit's CLUT port is ready (no probe before its texel stage), so a write
/// is ordered with the fragments around it.
///
/// stat_probes_o counts the probes issued to the trilinear unit since reset (wraps).
///
/// Example: 8 probes at most, heights, r1 = (8, 0), r2 = (0, 1) texels at (u, v) = (10, 20):
/// k = 3, lambda = 0 (the probes are one texel), probes at u = 10 + (-7, -5, ..., 7) / 2,
/// v = 20; the output is the mean of the 8 trilinear samples, rounded half up.
module tmu_footprint #(
  /// The trilinear unit's widths (tmu_trilinear; golden texram::Widths S, W, L).
  parameter int unsigned SubTexelBits = 8,
  parameter int unsigned WeightBits   = 8,
  parameter int unsigned LodFracBits  = 8,
  /// The setup's widths (golden footprint::Widths D, T, F).
  parameter int unsigned DerivBits    = 12,
  parameter int unsigned TableBits    = 7,
  parameter int unsigned LogFracBits  = 8
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  /// The trilinear unit's configuration (tmu_trilinear).
  input  tmu_pkg::mip_log2_t         cfg_log2_w_i,
  input  tmu_pkg::mip_log2_t         cfg_log2_h_i,
  input  tmu_pkg::tex_kind_t         cfg_kind_i,
  input  tmu_pkg::byte_plane_t       cfg_single_channel_i,
  input  tmu_pkg::tex_filter_t       cfg_filter_i,
  input  tmu_pkg::tex_border_t       cfg_border_u_i,
  input  tmu_pkg::tex_border_t       cfg_border_v_i,
  input  tmu_pkg::rgba8888_t         cfg_border_rgba_i,
  input  tmu_pkg::tex_combine_t      cfg_combine_i,
  input  tmu_pkg::rgba8888_t         cfg_constant_rgba_i,
  /// At most 2^cfg_log2_max_probes_i probes (0..4); the edge length q: 0 heights, 1 sides.
  input  tmu_pkg::probe_log2_t       cfg_log2_max_probes_i,
  input  tmu_pkg::q_rule_t           cfg_q_rule_i,

  /// CLUT write: entry clut_addr_i <= clut_rgba_i (ready only while no fragment is in flight
  /// before the trilinear unit's texel stage).
  input  logic                       clut_valid_i,
  output logic                       clut_ready_o,
  input  tmu_pkg::clut_index_t       clut_addr_i,
  input  tmu_pkg::rgba8888_t         clut_rgba_i,

  /// The fragment: centre (u, v), r1 = (r1u, r1v), r2 = (r2u, r2v), shade I_d.
  input  logic                       req_valid_i,
  output logic                       req_ready_o,
  input  tmu_pkg::tex_coord_t        req_u_i,
  input  tmu_pkg::tex_coord_t        req_v_i,
  input  tmu_pkg::tex_deriv_t        req_r1u_i,
  input  tmu_pkg::tex_deriv_t        req_r1v_i,
  input  tmu_pkg::tex_deriv_t        req_r2u_i,
  input  tmu_pkg::tex_deriv_t        req_r2v_i,
  input  tmu_pkg::rgba8888_t         req_shade_i,

  /// The trilinear unit's memory ports (tmu_trilinear).
  output logic                       mem_req_valid_o,
  input  logic                       mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]  mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  input  logic                       mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0] mem_resp_data_i,

  /// The fragment's colour, RGBA8888, one per request in request order.
  output logic                       out_valid_o,
  input  logic                       out_ready_i,
  output tmu_pkg::rgba8888_t         out_rgba_o,

  /// Probes issued to the trilinear unit since reset (wraps).
  output tmu_pkg::stat_count_t       stat_probes_o
);

  // texram::Border, as tmu_trilinear declares it: 0 wrap, 1 clamp, 2 border colour, 3 mirror.
  // A probe beyond the port's range saturates on clamp and border-colour axes, else wraps.
  localparam tmu_pkg::tex_border_t BorderClamp  = 2'd1;
  localparam tmu_pkg::tex_border_t BorderColour = 2'd2;
  localparam int unsigned StatW = tmu_pkg::StatCountW;

  // ---- Setup ----------------------------------------------------------------------------------

  logic                 plan_valid, plan_ready, setup_busy;
  tmu_pkg::tex_coord_t  plan_u, plan_v;
  tmu_pkg::tex_deriv_t  plan_du, plan_dv;
  tmu_pkg::rgba8888_t   plan_shade;
  tmu_pkg::probe_log2_t plan_log2_n;
  tmu_pkg::lod_t        plan_lambda;

  tmu_footprint_setup #(
    .DerivBits   (DerivBits),
    .TableBits   (TableBits),
    .LogFracBits (LogFracBits)
  ) u_setup (
    .clk_i                 (clk_i),
    .rst_ni                (rst_ni),
    .cfg_log2_max_probes_i (cfg_log2_max_probes_i),
    .cfg_q_rule_i          (cfg_q_rule_i),
    .req_valid_i           (req_valid_i),
    .req_ready_o           (req_ready_o),
    .req_u_i               (req_u_i),
    .req_v_i               (req_v_i),
    .req_r1u_i             (req_r1u_i),
    .req_r1v_i             (req_r1v_i),
    .req_r2u_i             (req_r2u_i),
    .req_r2v_i             (req_r2v_i),
    .req_shade_i           (req_shade_i),
    .plan_valid_o          (plan_valid),
    .plan_ready_i          (plan_ready),
    .plan_u_o              (plan_u),
    .plan_v_o              (plan_v),
    .plan_du_o             (plan_du),
    .plan_dv_o             (plan_dv),
    .plan_shade_o          (plan_shade),
    .plan_log2_n_o         (plan_log2_n),
    .plan_lambda_o         (plan_lambda),
    .stat_busy_o           (setup_busy)
  );

  // ---- Marcher --------------------------------------------------------------------------------

  logic                 frag_push, frag_full, march_busy;
  tmu_pkg::probe_log2_t frag_log2_n;
  logic                 probe_valid, probe_ready, probe_fire;
  tmu_pkg::tex_coord_t  probe_u, probe_v;
  tmu_pkg::lod_t        probe_lambda;
  tmu_pkg::rgba8888_t   probe_shade;

  tmu_footprint_march u_march (
    .clk_i            (clk_i),
    .rst_ni           (rst_ni),
    .cfg_saturate_u_i (cfg_border_u_i == BorderClamp || cfg_border_u_i == BorderColour),
    .cfg_saturate_v_i (cfg_border_v_i == BorderClamp || cfg_border_v_i == BorderColour),
    .plan_valid_i     (plan_valid),
    .plan_ready_o     (plan_ready),
    .plan_u_i         (plan_u),
    .plan_v_i         (plan_v),
    .plan_du_i        (plan_du),
    .plan_dv_i        (plan_dv),
    .plan_shade_i     (plan_shade),
    .plan_log2_n_i    (plan_log2_n),
    .plan_lambda_i    (plan_lambda),
    .frag_push_o      (frag_push),
    .frag_log2_n_o    (frag_log2_n),
    .frag_full_i      (frag_full),
    .probe_valid_o    (probe_valid),
    .probe_ready_i    (probe_ready),
    .probe_u_o        (probe_u),
    .probe_v_o        (probe_v),
    .probe_lambda_o   (probe_lambda),
    .probe_shade_o    (probe_shade),
    .busy_o           (march_busy)
  );

  // ---- Trilinear unit -------------------------------------------------------------------------

  logic               tri_clut_ready, tri_out_valid, tri_out_ready, idle;
  tmu_pkg::rgba8888_t tri_out_rgba;

  // A CLUT write waits until every fragment before it has left the setup and the marcher.
  assign idle         = !setup_busy && !march_busy;
  assign clut_ready_o = idle && tri_clut_ready;

  tmu_trilinear #(
    .SubTexelBits (SubTexelBits),
    .WeightBits   (WeightBits),
    .LodFracBits  (LodFracBits)
  ) u_trilinear (
    .clk_i                (clk_i),
    .rst_ni               (rst_ni),
    .cfg_log2_w_i         (cfg_log2_w_i),
    .cfg_log2_h_i         (cfg_log2_h_i),
    .cfg_kind_i           (cfg_kind_i),
    .cfg_single_channel_i (cfg_single_channel_i),
    .cfg_filter_i         (cfg_filter_i),
    .cfg_border_u_i       (cfg_border_u_i),
    .cfg_border_v_i       (cfg_border_v_i),
    .cfg_border_rgba_i    (cfg_border_rgba_i),
    .cfg_combine_i        (cfg_combine_i),
    .cfg_constant_rgba_i  (cfg_constant_rgba_i),
    .cfg_addressing_i     (1'b0),  // the probes are texels
    .clut_valid_i         (clut_valid_i && idle),
    .clut_ready_o         (tri_clut_ready),
    .clut_addr_i          (clut_addr_i),
    .clut_rgba_i          (clut_rgba_i),
    .req_valid_i          (probe_valid),
    .req_ready_o          (probe_ready),
    .req_u_i              (probe_u),
    .req_v_i              (probe_v),
    .req_lambda_i         (probe_lambda),
    .req_shade_i          (probe_shade),
    .mem_req_valid_o      (mem_req_valid_o),
    .mem_req_ready_i      (mem_req_ready_i),
    .mem_req_en_o         (mem_req_en_o),
    .mem_req_addr_o       (mem_req_addr_o),
    .mem_resp_valid_i     (mem_resp_valid_i),
    .mem_resp_data_i      (mem_resp_data_i),
    .out_valid_o          (tri_out_valid),
    .out_ready_i          (tri_out_ready),
    .out_rgba_o           (tri_out_rgba)
  );

  // ---- Average ----------------------------------------------------------------------------------

  tmu_footprint_average u_average (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .frag_push_i   (frag_push),
    .frag_log2_n_i (frag_log2_n),
    .frag_full_o   (frag_full),
    .in_valid_i    (tri_out_valid),
    .in_ready_o    (tri_out_ready),
    .in_rgba_i     (tri_out_rgba),
    .out_valid_o   (out_valid_o),
    .out_ready_i   (out_ready_i),
    .out_rgba_o    (out_rgba_o)
  );

  // ---- Statistics -------------------------------------------------------------------------------

  tmu_pkg::stat_count_t probes_q;
  assign probe_fire    = probe_valid && probe_ready;
  assign stat_probes_o = probes_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      probes_q <= '0;
    end else begin
      probes_q <= probes_q + StatW'(probe_fire);
    end
  end

`ifndef SYNTHESIS
  // The setup's and the marcher's configuration is held while fragments are in flight.
  property p_cfg_stable;
    @(posedge clk_i) disable iff (!rst_ni)
      !idle |=> ($stable(cfg_log2_max_probes_i) && $stable(cfg_q_rule_i) &&
                 $stable(cfg_border_u_i) && $stable(cfg_border_v_i));
  endproperty
  a_cfg_stable: assert property (p_cfg_stable);
`endif

endmodule
