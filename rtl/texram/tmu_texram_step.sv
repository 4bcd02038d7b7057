/// One step of the TEXRAM chip's sequencer (docs/texram_chip.md "The chip block"), bit-exact
/// with golden texram::chip::sample_step (golden/texram/chip/chip_step.cpp): the sample of DRF
/// t for a pixel's parameter, with footprint assembly (000 §10) and a detail map (000 §9) as
/// t's control word says, through the chip's one trilinear unit.
///
///   request ─┬─ footprint off ──────────────────────────┐  probes
///            └─ tmu_footprint_setup ─ tmu_footprint_march ┤
///                                                         ├─ lambda >= 0, or no detail map:
///                                                         │  straight into tmu_trilinear
///                                                         └─ detail path: tmu_texram_detail,
///                                                            its reads one at a time
///   probe colours ── footprint: tmu_footprint_average ── the step's sample
///
/// A probe takes the detail path when t has the detail flag, its lambda is negative and t's
/// link o and o's link d are DRFs (golden's conditions; the ops are not checked). A footprint
/// step's probes share one lambda, so all of a step's probes take one path. Straight probes
/// go into the unit one per clock while it is ready (N probes of a footprint step pipeline like
/// tmu_footprint's); the detail unit takes a probe only when no straight sample is in flight,
/// and while it holds one the unit is its alone. The unit's configuration is the DRF file's map
/// port, which this module points at t, or at the detail unit's read's DRF (o, d, or t with eq.
/// 5 "one"), and every address gets that map's base (the cube face's for t on DRF 7's cube
/// map, o's own base plus the v-offset map's distance, d's own base) added: the port changes
/// only while the unit is empty.
///
/// The footprint setup takes t's log2_max_probes (5..7 act as 4, golden's min) and q rule; the
/// marcher wraps or saturates by t's border modes, as golden footprint::probe.
///
/// Latency at page hits, nothing stalled, from the request accepted to the sample valid: 12
/// for one straight sample (the unit's); 8 + (N - 1) + 12 + 1 = 20 + N with footprint assembly
/// (tmu_footprint's); a detail probe 13 per read plus 2 (tmu_texram_detail), N of them one
/// after the other with footprint assembly.
module tmu_texram_step (
  input  logic                         clk_i,
  input  logic                         rst_ni,

  /// The step's DRF t, its link o and o's link d (0: none); held for the step.
  input  tmu_pkg::drf_index_t          t_i,
  input  tmu_pkg::drf_index_t          o_i,
  input  tmu_pkg::drf_index_t          d_i,
  /// t's control (the DRF file's control port), held for the step.
  input  logic                         footprint_i,
  input  tmu_pkg::probe_log2_t         log2_max_probes_i,
  input  tmu_pkg::q_rule_t             q_rule_i,
  input  logic                         detail_i,
  input  tmu_pkg::tex_detail_combine_t detail_combine_i,
  input  tmu_pkg::tex_border_t         border_u_i,
  input  tmu_pkg::tex_border_t         border_v_i,
  input  tmu_pkg::tex_combine_t        combine_i,
  input  tmu_pkg::rgba8888_t           constant_rgba_i,

  /// The DRF file's map port: the DRF to show, its own base rather than a cube face's ...
  output tmu_pkg::drf_index_t          map_drf_o,
  output logic                         map_own_base_o,
  /// ... and what it shows.
  input  tmu_pkg::bank_addr_t          map_base_i,
  input  tmu_pkg::mip_log2_t           map_log2_w_i,
  input  tmu_pkg::mip_log2_t           map_log2_h_i,
  input  tmu_pkg::tex_kind_t           map_kind_i,
  input  tmu_pkg::byte_plane_t         map_single_channel_i,
  input  tmu_pkg::tex_filter_t         map_filter_i,
  input  tmu_pkg::tex_border_t         map_border_u_i,
  input  tmu_pkg::tex_border_t         map_border_v_i,
  input  tmu_pkg::tex_addressing_t     map_addressing_i,
  input  tmu_pkg::rgba8888_t           map_border_rgba_i,
  input  tmu_pkg::rgba8888_t           map_constant_rgba_i,
  input  tmu_pkg::tex_combine_t        map_combine_i,

  /// The trilinear unit's CLUT write port (the chip gates it to its idle state).
  input  logic                         clut_valid_i,
  output logic                         clut_ready_o,
  input  tmu_pkg::clut_index_t         clut_addr_i,
  input  tmu_pkg::rgba8888_t           clut_rgba_i,

  /// The step: the parameter's (u, v), lambda, r1, r2 and the pixel's shade I_d.
  input  logic                         req_valid_i,
  output logic                         req_ready_o,
  input  tmu_pkg::tex_coord_t          req_u_i,
  input  tmu_pkg::tex_coord_t          req_v_i,
  input  tmu_pkg::lod_t                req_lambda_i,
  input  tmu_pkg::rgba8888_t           req_shade_i,
  input  tmu_pkg::tex_deriv_t          req_r1u_i,
  input  tmu_pkg::tex_deriv_t          req_r1v_i,
  input  tmu_pkg::tex_deriv_t          req_r2u_i,
  input  tmu_pkg::tex_deriv_t          req_r2v_i,

  /// Memory access, absolute addresses (tmu_texram_chip).
  output logic                         mem_req_valid_o,
  input  logic                         mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]    mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  input  logic                         mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0]  mem_resp_data_i,

  /// The step's sample.
  output logic                         out_valid_o,
  input  logic                         out_ready_i,
  output tmu_pkg::rgba8888_t           out_rgba_o
);

  localparam int unsigned Banks = tmu_pkg::Banks;
  localparam int unsigned AddrW = tmu_pkg::BankAddrW;
  localparam int unsigned CntW  = 5;  // samples in the trilinear unit: at most its 13 stages
  localparam tmu_pkg::tex_border_t  BorderClamp  = 2'd1;
  localparam tmu_pkg::tex_border_t  BorderColour = 2'd2;
  localparam tmu_pkg::tex_kind_t    KindCcc      = 3'd4;
  localparam tmu_pkg::tex_combine_t CombineOne   = 2'd0;
  localparam logic [1:0]            MapO = 2'd1;
  localparam logic [1:0]            MapD = 2'd2;

  // ---- Footprint: setup and marcher -----------------------------------------------------------

  logic                 fp_req_valid, fp_req_ready;
  logic                 plan_valid, plan_ready, setup_busy, march_busy;
  tmu_pkg::tex_coord_t  plan_u, plan_v;
  tmu_pkg::tex_deriv_t  plan_du, plan_dv;
  tmu_pkg::rgba8888_t   plan_shade;
  tmu_pkg::probe_log2_t plan_log2_n, max_probes;
  tmu_pkg::lod_t        plan_lambda;

  assign fp_req_valid = req_valid_i && footprint_i;
  // 5..7 act as 4 (golden: min(log2_max_probes, MaxProbeLog2)).
  assign max_probes   = log2_max_probes_i > 3'(tmu_pkg::MaxProbeLog2) ?
                        3'(tmu_pkg::MaxProbeLog2) : log2_max_probes_i;

  tmu_footprint_setup u_setup (
    .clk_i                 (clk_i),
    .rst_ni                (rst_ni),
    .cfg_log2_max_probes_i (max_probes),
    .cfg_q_rule_i          (q_rule_i),
    .req_valid_i           (fp_req_valid),
    .req_ready_o           (fp_req_ready),
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

  logic                 frag_push, frag_full;
  tmu_pkg::probe_log2_t frag_log2_n;
  logic                 probe_valid, probe_ready;
  tmu_pkg::tex_coord_t  probe_u, probe_v;
  tmu_pkg::lod_t        probe_lambda;
  tmu_pkg::rgba8888_t   probe_shade;

  tmu_footprint_march u_march (
    .clk_i            (clk_i),
    .rst_ni           (rst_ni),
    .cfg_saturate_u_i (border_u_i == BorderClamp || border_u_i == BorderColour),
    .cfg_saturate_v_i (border_v_i == BorderClamp || border_v_i == BorderColour),
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

  // ---- Probes: the marcher's, or the request itself -------------------------------------------

  logic                src_valid, src_ready, detail_path;
  tmu_pkg::tex_coord_t src_u, src_v;
  tmu_pkg::lod_t       src_lambda;
  tmu_pkg::rgba8888_t  src_shade;

  assign src_valid   = footprint_i ? probe_valid : req_valid_i;
  assign src_u       = footprint_i ? probe_u : req_u_i;
  assign src_v       = footprint_i ? probe_v : req_v_i;
  assign src_lambda  = footprint_i ? probe_lambda : req_lambda_i;
  assign src_shade   = footprint_i ? probe_shade : req_shade_i;
  assign probe_ready = footprint_i && src_ready;
  assign req_ready_o = footprint_i ? fp_req_ready : src_ready;
  assign detail_path = detail_i && src_lambda < 0 && o_i != '0 && d_i != '0;

  // The trilinear unit's request and sample handshakes (the unit below).
  logic                   tri_req_valid, tri_req_ready, tri_req_fire;
  logic                   tri_out_valid, tri_out_ready, tri_out_fire;
  tmu_pkg::rgba8888_t     tri_out_rgba;

  // ---- The detail unit ------------------------------------------------------------------------

  logic                eng_in_valid, eng_in_ready, eng_busy;
  logic                eng_rd_valid, eng_rd_ready, eng_rd_one;
  logic [1:0]          eng_rd_map;
  tmu_pkg::bank_addr_t eng_base_add;
  tmu_pkg::tex_coord_t eng_rd_u, eng_rd_v;
  tmu_pkg::lod_t       eng_rd_lambda;
  tmu_pkg::rgba8888_t  eng_rd_shade;
  logic                eng_res_valid, eng_res_ready;
  logic                eng_out_valid, eng_out_ready;
  tmu_pkg::rgba8888_t  eng_out_rgba;
  logic [CntW-1:0]     in_flight_q;  // samples in the trilinear unit

  assign eng_in_valid = src_valid && detail_path && in_flight_q == '0;

  tmu_texram_detail u_detail (
    .clk_i            (clk_i),
    .rst_ni           (rst_ni),
    .modulate_i       (detail_combine_i),
    .combine_i        (combine_i),
    .constant_rgba_i  (constant_rgba_i),
    .in_valid_i       (eng_in_valid),
    .in_ready_o       (eng_in_ready),
    .in_u_i           (src_u),
    .in_v_i           (src_v),
    .in_lambda_i      (src_lambda),
    .in_shade_i       (src_shade),
    .rd_valid_o       (eng_rd_valid),
    .rd_ready_i       (eng_rd_ready),
    .rd_map_o         (eng_rd_map),
    .rd_base_add_o    (eng_base_add),
    .rd_one_o         (eng_rd_one),
    .rd_u_o           (eng_rd_u),
    .rd_v_o           (eng_rd_v),
    .rd_lambda_o      (eng_rd_lambda),
    .rd_shade_o       (eng_rd_shade),
    .map_log2_w_i     (map_log2_w_i),
    .map_log2_h_i     (map_log2_h_i),
    .map_filter_i     (map_filter_i),
    .map_border_u_i   (map_border_u_i),
    .map_border_v_i   (map_border_v_i),
    .map_addressing_i (map_addressing_i),
    .map_block_grid_i (map_kind_i == KindCcc),
    .res_valid_i      (eng_res_valid),
    .res_ready_o      (eng_res_ready),
    .res_rgba_i       (tri_out_rgba),
    .out_valid_o      (eng_out_valid),
    .out_ready_i      (eng_out_ready),
    .out_rgba_o       (eng_out_rgba),
    .busy_o           (eng_busy)
  );

  // ---- The trilinear unit on the map port -----------------------------------------------------

  tmu_pkg::tex_coord_t    tri_u, tri_v;
  tmu_pkg::lod_t          tri_lambda;
  tmu_pkg::rgba8888_t     tri_shade;
  logic [Banks*AddrW-1:0] tri_addr;
  tmu_pkg::bank_addr_t    base;

  // Straight probes while the detail unit is idle; its reads while it holds a probe.
  assign tri_req_valid = eng_busy ? eng_rd_valid : src_valid && !detail_path;
  assign eng_rd_ready  = eng_busy && tri_req_ready;
  assign src_ready     = detail_path ? eng_in_ready && in_flight_q == '0
                                     : !eng_busy && tri_req_ready;
  assign tri_u         = eng_busy ? eng_rd_u : src_u;
  assign tri_v         = eng_busy ? eng_rd_v : src_v;
  assign tri_lambda    = eng_busy ? eng_rd_lambda : src_lambda;
  assign tri_shade     = eng_busy ? eng_rd_shade : src_shade;

  assign map_drf_o      = !eng_busy          ? t_i
                        : eng_rd_map == MapO ? o_i
                        : eng_rd_map == MapD ? d_i : t_i;
  assign map_own_base_o = eng_busy && (eng_rd_map == MapO || eng_rd_map == MapD);
  assign base           = map_base_i + (eng_busy ? eng_base_add : '0);

  tmu_trilinear u_trilinear (
    .clk_i                (clk_i),
    .rst_ni               (rst_ni),
    .cfg_log2_w_i         (map_log2_w_i),
    .cfg_log2_h_i         (map_log2_h_i),
    .cfg_kind_i           (map_kind_i),
    .cfg_single_channel_i (map_single_channel_i),
    .cfg_filter_i         (map_filter_i),
    .cfg_border_u_i       (map_border_u_i),
    .cfg_border_v_i       (map_border_v_i),
    .cfg_border_rgba_i    (map_border_rgba_i),
    .cfg_combine_i        (eng_busy && eng_rd_one ? CombineOne : map_combine_i),
    .cfg_constant_rgba_i  (map_constant_rgba_i),
    .cfg_addressing_i     (map_addressing_i),
    .clut_valid_i         (clut_valid_i),
    .clut_ready_o         (clut_ready_o),
    .clut_addr_i          (clut_addr_i),
    .clut_rgba_i          (clut_rgba_i),
    .req_valid_i          (tri_req_valid),
    .req_ready_o          (tri_req_ready),
    .req_u_i              (tri_u),
    .req_v_i              (tri_v),
    .req_lambda_i         (tri_lambda),
    .req_shade_i          (tri_shade),
    .mem_req_valid_o      (mem_req_valid_o),
    .mem_req_ready_i      (mem_req_ready_i),
    .mem_req_en_o         (mem_req_en_o),
    .mem_req_addr_o       (tri_addr),
    .mem_resp_valid_i     (mem_resp_valid_i),
    .mem_resp_data_i      (mem_resp_data_i),
    .out_valid_o          (tri_out_valid),
    .out_ready_i          (tri_out_ready),
    .out_rgba_o           (tri_out_rgba)
  );

  // The map's base on every bank it reads; 0 where not read.
  for (genvar b = 0; b < Banks; b++) begin : gen_addr
    assign mem_req_addr_o[b*AddrW +: AddrW] =
        mem_req_en_o[b] ? tri_addr[b*AddrW +: AddrW] + base : '0;
  end

  assign tri_req_fire = tri_req_valid && tri_req_ready;
  assign tri_out_fire = tri_out_valid && tri_out_ready;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_flight_q <= '0;
    end else begin
      in_flight_q <= in_flight_q + CntW'(tri_req_fire) - CntW'(tri_out_fire);
    end
  end

  // ---- Colours: the unit's straight samples or the detail unit's, then the average -----------

  logic               col_valid, col_ready;
  tmu_pkg::rgba8888_t col_rgba;

  assign eng_res_valid = eng_busy && tri_out_valid;
  assign tri_out_ready = eng_busy ? eng_res_ready : col_ready;
  assign col_valid     = eng_out_valid || (!eng_busy && tri_out_valid);
  assign col_rgba      = eng_out_valid ? eng_out_rgba : tri_out_rgba;
  assign eng_out_ready = col_ready;

  logic               avg_in_ready, avg_out_valid;
  tmu_pkg::rgba8888_t avg_out_rgba;

  // A k per fragment from the marcher's start to its last probe's colour: 16 covers the
  // trilinear unit's samples in flight when the chip streams one-probe fragments (as
  // tmu_footprint's); 2 held its pixels two at a time, 13 cycles apart.
  tmu_footprint_average #(.Depth(16)) u_average (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .frag_push_i   (frag_push),
    .frag_log2_n_i (frag_log2_n),
    .frag_full_o   (frag_full),
    .in_valid_i    (footprint_i && col_valid),
    .in_ready_o    (avg_in_ready),
    .in_rgba_i     (col_rgba),
    .out_valid_o   (avg_out_valid),
    .out_ready_i   (footprint_i && out_ready_i),
    .out_rgba_o    (avg_out_rgba)
  );

  assign col_ready   = footprint_i ? avg_in_ready : out_ready_i;
  assign out_valid_o = footprint_i ? avg_out_valid : col_valid;
  assign out_rgba_o  = footprint_i ? avg_out_rgba : col_rgba;

  // The setup's and the marcher's busy flags are for their own users.
  logic unused_busy;
  assign unused_busy = setup_busy ^ march_busy;

`ifndef SYNTHESIS
  // The unit's configuration (the map port) holds while it has samples.
  property p_map_stable;
    @(posedge clk_i) disable iff (!rst_ni)
      !($stable(map_drf_o) && $stable(map_own_base_o) && $stable(base)) |-> in_flight_q == '0;
  endproperty
  a_map_stable: assert property (p_map_stable);
  // A step's probes take one path (they share one lambda): no straight sample is left when
  // the detail unit takes a probe, none is issued while it holds one.
  property p_one_owner;
    @(posedge clk_i) disable iff (!rst_ni) eng_busy |-> !(src_valid && src_ready && !detail_path);
  endproperty
  a_one_owner: assert property (p_one_owner);
`endif

endmodule
