/// Footprint assembly on a clip-map (000 §10 in front of 003), bit-exact with golden
/// clipmap::footprint_sample (golden/clipmap/clip_footprint.hpp): the footprint unit's setup,
/// marcher and average (tmu_footprint's, unchanged) with the clip-map address unit
/// (tmu_clipmap) in the trilinear unit's place, so that the marcher's probes read the clip-map
/// like every other sample: virtual coordinates, per-probe substitution, the load port.
///
///   tmu_footprint_setup    k = log2 N, lambda, the direction (7 stages)
///   tmu_footprint_march    the N probes, one per clock (virtual texels, wrapped or saturated)
///   tmu_clipmap            one clip-map sample per probe, eq. 5 with the fragment's shade
///   tmu_footprint_average  per channel (sum + N/2) >> k
///
/// Latency with page hits: 8 cycles to the first probe, the clip-map's 14 to its colour, 1 to
/// the average: 23 + (N - 1) cycles from request to output. A probe per clock while the
/// clip-map takes one.
///
/// Writes (CLUT, region, load) are the clip-map's, taken only while no fragment is in the setup
/// or the marcher and the clip-map's port is ready: a write is ordered after every probe of the
/// fragments before it and before those after it (the clip-map orders its own ports with the
/// probes it holds). A fragment offered with a write in one cycle is taken too and comes after
/// it.
///
/// Configuration (cfg_*): the clip-map's (tmu_clipmap) and the setup's maximum probe count and
/// q rule (tmu_footprint), quasi-static while fragments are in flight.
///
/// Counters (wrap): probes issued to the clip-map, and the clip-map's own (per probe).
module tmu_footprint_clip #(
  /// The clip-map's filter and level weight bits (golden Widths::weight).
  parameter int unsigned WeightBits  = 8,
  /// The setup's widths (golden footprint::Widths D, T, F).
  parameter int unsigned DerivBits   = 12,
  parameter int unsigned TableBits   = 7,
  parameter int unsigned LogFracBits = 8
) (
  input  logic                        clk_i,
  input  logic                        rst_ni,

  /// The clip-map's configuration (tmu_clipmap), then the setup's (tmu_footprint).
  input  tmu_pkg::clip_log2_t         cfg_log2_virtual_i,
  input  tmu_pkg::mip_log2_t          cfg_log2_tile_i,
  input  tmu_pkg::tex_kind_t          cfg_kind_i,
  input  tmu_pkg::byte_plane_t        cfg_single_channel_i,
  input  tmu_pkg::tex_filter_t        cfg_filter_i,
  input  tmu_pkg::tex_border_t        cfg_border_u_i,
  input  tmu_pkg::tex_border_t        cfg_border_v_i,
  input  tmu_pkg::rgba8888_t          cfg_border_rgba_i,
  input  tmu_pkg::tex_combine_t       cfg_combine_i,
  input  tmu_pkg::rgba8888_t          cfg_constant_rgba_i,
  input  tmu_pkg::clip_substitution_t cfg_substitution_i,
  input  tmu_pkg::probe_log2_t        cfg_log2_max_probes_i,
  input  tmu_pkg::q_rule_t            cfg_q_rule_i,

  /// CLUT, region and load writes (tmu_clipmap).
  input  logic                        clut_valid_i,
  output logic                        clut_ready_o,
  input  tmu_pkg::clut_index_t        clut_addr_i,
  input  tmu_pkg::rgba8888_t          clut_rgba_i,
  input  logic                        region_valid_i,
  output logic                        region_ready_o,
  input  tmu_pkg::mip_level_t         region_level_i,
  input  tmu_pkg::clip_bound_t        region_x0_i,
  input  tmu_pkg::clip_bound_t        region_y0_i,
  input  tmu_pkg::clip_bound_t        region_x1_i,
  input  tmu_pkg::clip_bound_t        region_y1_i,
  input  logic                        load_valid_i,
  output logic                        load_ready_o,
  input  tmu_pkg::mip_level_t         load_level_i,
  input  tmu_pkg::clip_coord_t        load_x_i,
  input  tmu_pkg::clip_coord_t        load_y_i,
  input  tmu_pkg::rgba8888_t          load_texel_i,

  /// The fragment: centre (u, v) in virtual texels, r1, r2, shade I_d.
  input  logic                        req_valid_i,
  output logic                        req_ready_o,
  input  tmu_pkg::tex_coord_t         req_u_i,
  input  tmu_pkg::tex_coord_t         req_v_i,
  input  tmu_pkg::tex_deriv_t         req_r1u_i,
  input  tmu_pkg::tex_deriv_t         req_r1v_i,
  input  tmu_pkg::tex_deriv_t         req_r2u_i,
  input  tmu_pkg::tex_deriv_t         req_r2v_i,
  input  tmu_pkg::rgba8888_t          req_shade_i,

  /// The clip-map's memory port (reads and the loads' writes).
  output logic                        mem_req_valid_o,
  input  logic                        mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]   mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  output logic                        mem_req_we_o,
  output logic [tmu_pkg::Banks*8-1:0] mem_req_wdata_o,
  input  logic                        mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0] mem_resp_data_i,

  /// The fragment's colour, RGBA8888, in order.
  output logic                        out_valid_o,
  input  logic                        out_ready_i,
  output tmu_pkg::rgba8888_t          out_rgba_o,

  /// Counters (wrap).
  output tmu_pkg::stat_count_t        stat_probes_o,
  output tmu_pkg::stat_count_t        stat_wayward_samples_o,
  output tmu_pkg::stat_count_t        stat_substituted_taps_o,
  output tmu_pkg::stat_count_t        stat_conflicts_o
);

  // texram::Border: 1 clamp, 2 border colour saturate a probe beyond the port; else it wraps.
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

  // ---- Clip-map -------------------------------------------------------------------------------

  logic               clip_clut_ready, clip_region_ready, clip_load_ready;
  logic               clip_out_valid, clip_out_ready, idle;
  tmu_pkg::rgba8888_t clip_out_rgba;

  // A write waits until every fragment before it has left the setup and the marcher.
  assign idle           = !setup_busy && !march_busy;
  assign clut_ready_o   = idle && clip_clut_ready;
  assign region_ready_o = idle && clip_region_ready;
  assign load_ready_o   = idle && clip_load_ready;

  tmu_clipmap #(
    .WeightBits (WeightBits)
  ) u_clipmap (
    .clk_i                   (clk_i),
    .rst_ni                  (rst_ni),
    .cfg_log2_virtual_i      (cfg_log2_virtual_i),
    .cfg_log2_tile_i         (cfg_log2_tile_i),
    .cfg_kind_i              (cfg_kind_i),
    .cfg_single_channel_i    (cfg_single_channel_i),
    .cfg_filter_i            (cfg_filter_i),
    .cfg_border_u_i          (cfg_border_u_i),
    .cfg_border_v_i          (cfg_border_v_i),
    .cfg_border_rgba_i       (cfg_border_rgba_i),
    .cfg_combine_i           (cfg_combine_i),
    .cfg_constant_rgba_i     (cfg_constant_rgba_i),
    .cfg_substitution_i      (cfg_substitution_i),
    .clut_valid_i            (clut_valid_i && idle),
    .clut_ready_o            (clip_clut_ready),
    .clut_addr_i             (clut_addr_i),
    .clut_rgba_i             (clut_rgba_i),
    .region_valid_i          (region_valid_i && idle),
    .region_ready_o          (clip_region_ready),
    .region_level_i          (region_level_i),
    .region_x0_i             (region_x0_i),
    .region_y0_i             (region_y0_i),
    .region_x1_i             (region_x1_i),
    .region_y1_i             (region_y1_i),
    .load_valid_i            (load_valid_i && idle),
    .load_ready_o            (clip_load_ready),
    .load_level_i            (load_level_i),
    .load_x_i                (load_x_i),
    .load_y_i                (load_y_i),
    .load_texel_i            (load_texel_i),
    .req_valid_i             (probe_valid),
    .req_ready_o             (probe_ready),
    .req_u_i                 (probe_u),
    .req_v_i                 (probe_v),
    .req_lambda_i            (probe_lambda),
    .req_shade_i             (probe_shade),
    .mem_req_valid_o         (mem_req_valid_o),
    .mem_req_ready_i         (mem_req_ready_i),
    .mem_req_en_o            (mem_req_en_o),
    .mem_req_addr_o          (mem_req_addr_o),
    .mem_req_we_o            (mem_req_we_o),
    .mem_req_wdata_o         (mem_req_wdata_o),
    .mem_resp_valid_i        (mem_resp_valid_i),
    .mem_resp_data_i         (mem_resp_data_i),
    .out_valid_o             (clip_out_valid),
    .out_ready_i             (clip_out_ready),
    .out_rgba_o              (clip_out_rgba),
    .stat_wayward_samples_o  (stat_wayward_samples_o),
    .stat_substituted_taps_o (stat_substituted_taps_o),
    .stat_conflicts_o        (stat_conflicts_o)
  );

  // ---- Average ----------------------------------------------------------------------------------

  tmu_footprint_average u_average (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .frag_push_i   (frag_push),
    .frag_log2_n_i (frag_log2_n),
    .frag_full_o   (frag_full),
    .in_valid_i    (clip_out_valid),
    .in_ready_o    (clip_out_ready),
    .in_rgba_i     (clip_out_rgba),
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
