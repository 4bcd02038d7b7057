/// The TEXRAM chip (000 §14; docs/texram_chip.md "The chip block"), bit-exact with the golden
/// sequencer texram::chip::TexramChip (golden/texram/chip/texram_chip.cpp, the specification):
/// seven linked description register files (tmu_texram_drf_file) over one shared memory, one
/// step of a chain at a time in tmu_texram_step (the trilinear unit as the datapath of every
/// map, footprint assembly and detail maps), eq. 6-7 in tmu_specular_combine.
///
/// A pixel's first parameter names its leading DRF. For each DRF of its chain the sequencer
/// takes the pixel's next parameter first where the DRF says takes_coords (not for the first
/// DRF, whose parameter is the first), samples the DRF's map (tmu_texram_step: the trilinear
/// unit with the DRF's cfg_*, every memory address with the map's base added: the base, or the
/// cube face's base for DRF 7's cube map, the face taken modulo 6; N probes averaged with the
/// footprint flag; with the detail flag and lambda < 0 the offsets and detail maps of the two
/// DRFs it links to), and does the DRF's op with the sample:
///   texture      C_d = the sample (eq. 5 inside the trilinear unit, with the pixel's I_d)
///   shading      I_d = the sample (and a later parameter's shade no longer replaces it)
///   reflectance  R = the sample
///   environment  E = the sample; R = the DRF's constant unless a reflectance map gave it
///   emit         the sample leaves on out at once, last = 0
/// then follows the link (0 ends the chain; past a detail map's two DRFs, which count as two more
/// steps). The colour leaves last = 1: C_d, or specular_combine(C_d, E, R) once an environment
/// was sampled. After 7 steps the pixel ends where it is and stat_step_limit_o is set (sticky).
///
/// One step at a time: the trilinear unit documents its configuration as quasi-static, so
/// cfg_* (a DRF's fields) change only while it is empty (tmu_texram_step); except that pixels
/// whose chain is one texture step stream (StStream, below). States:
///   StIdle     drf and clut writes and a pixel's first parameter are taken
///   StCheck    the DRF number: 0 ends, the 8th step ends with the limit, a takes_coords DRF
///              (not the first) waits for a parameter, else the access
///   StParam    the pixel's next parameter
///   StIssue    the step's request to tmu_texram_step
///   StWait     its sample, applied by the op (an emit waits for the output register)
///   StFinish   the colour: into the output register, or into tmu_specular_combine
///   StCombine  tmu_specular_combine's result into the output register
///   StStream   pixels led by the same streamable DRF go into the trilinear unit one a clock
///
/// Streaming (the patent's rate, 000 §5: a sample an access): a DRF is streamable when its
/// chain is that one step and nothing in it changes under the trilinear unit: op texture or
/// emit, link 0, no detail flag (its reads alternate three DRFs' maps), and not DRF 7 (its cube
/// faces' bases change with the pixel); with footprint assembly or without (the probes of the
/// next pixels follow the ones before, one a clock). Such a pixel's colour is its sample (C_d,
/// no environment), or for an emit its sample (last 0) and then C_d = 0 (last 1, the next
/// clock), so the pixels need no context of their own: the first is issued as usual (Idle,
/// Check, Issue), and from then on each next parameter led by the same DRF goes straight into
/// the unit while it is ready, up to MaxInFlight pixels in it, and each sample leaves in order.
/// A parameter led by another DRF, or a write, waits until the unit is empty; the sequencer
/// then returns to Idle. Outputs, memory requests and counters are the one-at-a-time
/// sequencer's (golden's), only sooner: 1 cycle a pixel on a one-plane map, 4 on four planes,
/// N with N footprint probes, 2 for an emit (tests/blocks/texram_chip_test.cpp).
///
/// Cycles per step with page hits, the output free: Check 1, Issue 1 and the trilinear unit's
/// 12 from acceptance to its output (taken in Wait): 14 for a one-plane map, 17 for four byte
/// planes, 1 more per page fault; with footprint assembly 22 + N (tmu_texram_step); a detail
/// sample 2 + 2 + 13 per read (3 or 4 reads). A pixel adds 3 (Idle, the last Check, Finish),
/// 2 more when an environment sends its colour through the combine
/// (tests/blocks/texram_chip_test.cpp).
///
/// The DRF and CLUT write ports are ready only in StIdle: no pixel is between the parameter
/// port and the output (the colour may still wait in the output register), so a write never
/// changes the program or the palette under a pixel; a write and a first parameter accepted
/// at the same edge take effect in that order.
module tmu_texram_chip (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  /// DRF write: DRF drf_drf_i's field drf_field_i <= drf_value_i (tmu_texram_drf_file).
  input  logic                       drf_valid_i,
  output logic                       drf_ready_o,
  input  tmu_pkg::drf_index_t        drf_drf_i,
  input  tmu_pkg::drf_field_t        drf_field_i,
  input  tmu_pkg::drf_value_t        drf_value_i,

  /// CLUT write (the chip's one palette, the trilinear unit's CLUT).
  input  logic                       clut_valid_i,
  output logic                       clut_ready_o,
  input  tmu_pkg::clut_index_t       clut_addr_i,
  input  tmu_pkg::rgba8888_t         clut_rgba_i,

  /// A pixel's parameter: the first names the leading DRF (param_lead_i; read from the first
  /// only); (u, v) texels of level 0 or a sphere map's (uN, vN), lambda, the shade I_d, the
  /// cube face, and the derivatives r1 = d(u,v)/dx, r2 = d(u,v)/dy for footprint assembly.
  input  logic                       param_valid_i,
  output logic                       param_ready_o,
  input  tmu_pkg::drf_index_t        param_lead_i,
  input  tmu_pkg::tex_coord_t        param_u_i,
  input  tmu_pkg::tex_coord_t        param_v_i,
  input  tmu_pkg::lod_t              param_lambda_i,
  input  tmu_pkg::rgba8888_t         param_shade_i,
  input  tmu_pkg::cube_face_t        param_face_i,
  input  tmu_pkg::tex_deriv_t        param_r1u_i,
  input  tmu_pkg::tex_deriv_t        param_r1v_i,
  input  tmu_pkg::tex_deriv_t        param_r2u_i,
  input  tmu_pkg::tex_deriv_t        param_r2v_i,

  /// Memory access: the banks to read and their absolute addresses (base + the map's cell; 0
  /// where not read) ...
  output logic                       mem_req_valid_o,
  input  logic                       mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]  mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  /// ... and its response, in request order, no ready: bank b's byte at [8 b +: 8].
  input  logic                       mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0] mem_resp_data_i,

  /// An emitted sample (last 0) or the pixel's colour (last 1).
  output logic                       out_valid_o,
  input  logic                       out_ready_i,
  output tmu_pkg::rgba8888_t         out_rgba_o,
  output tmu_pkg::flag_t             out_last_o,

  /// Pixels, parameters taken, steps (map samples); step_limit: sticky.
  output tmu_pkg::stat_count_t       stat_pixels_o,
  output tmu_pkg::stat_count_t       stat_parameters_o,
  output tmu_pkg::stat_count_t       stat_steps_o,
  output tmu_pkg::flag_t             stat_step_limit_o
);

  localparam int unsigned MaxSteps = tmu_pkg::Drfs;  // 7 steps per pixel
  localparam int unsigned LinkW    = tmu_pkg::DrfIndexW;

  // The ops (golden DrfOp); 5..7 do nothing.
  localparam logic [2:0] OpTexture     = 3'd0;
  localparam logic [2:0] OpShading     = 3'd1;
  localparam logic [2:0] OpReflectance = 3'd2;
  localparam logic [2:0] OpEnvironment = 3'd3;
  localparam logic [2:0] OpEmit        = 3'd4;

  typedef enum logic [2:0] {
    StIdle,
    StCheck,
    StParam,
    StIssue,
    StWait,
    StFinish,
    StCombine,
    StStream
  } state_e;

  // Pixels in the trilinear unit at once while streaming: more than its 12-cycle latency, so
  // that one-plane samples issue one a clock.
  localparam int unsigned MaxInFlight = 16;
  localparam int unsigned InFlightW   = $clog2(MaxInFlight + 1);

  // ---- Registers -----------------------------------------------------------------------------

  state_e                 state_q, state_d;
  tmu_pkg::drf_index_t    num_q, num_d;    // the current DRF (0: the chain has ended)
  logic [3:0]             step_q, step_d;  // steps so far, 0..9 (a detail map's count 3)
  tmu_pkg::tex_coord_t    u_q, u_d, v_q, v_d;
  tmu_pkg::lod_t          lambda_q, lambda_d;
  tmu_pkg::cube_face_t    face_q, face_d;
  tmu_pkg::tex_deriv_t    r1u_q, r1u_d, r1v_q, r1v_d, r2u_q, r2u_d, r2v_q, r2v_d;
  tmu_pkg::rgba8888_t     shade_q, shade_d;      // I_d
  tmu_pkg::rgba8888_t     colour_q, colour_d;    // C_d
  tmu_pkg::rgba8888_t     refl_q, refl_d;        // R
  tmu_pkg::rgba8888_t     env_q, env_d;          // E
  logic                   have_refl_q, have_refl_d, have_env_q, have_env_d;
  logic                   shaded_q, shaded_d;    // I_d from a shading map
  logic                   out_valid_q, out_valid_d;
  tmu_pkg::rgba8888_t     out_rgba_q, out_rgba_d;
  logic                   out_last_q, out_last_d;
  tmu_pkg::stat_count_t   pixels_q, pixels_d, params_q, params_d, steps_q, steps_d;
  logic                   limit_q, limit_d;
  logic [InFlightW-1:0]   in_flight_q, in_flight_d;  // streamed pixels in the unit
  logic                   colour_due_q, colour_due_d;  // a streamed emit's colour to send

  // ---- The DRF file --------------------------------------------------------------------------

  logic drf_fire, clut_fire, param_fire;
  // The map port, pointed by the step at the DRF whose map the trilinear unit reads.
  tmu_pkg::drf_index_t     map_drf;
  logic                    map_own_base;
  tmu_pkg::bank_addr_t     base;
  tmu_pkg::mip_log2_t      log2_w, log2_h;
  tmu_pkg::tex_kind_t      kind;
  tmu_pkg::byte_plane_t    single_channel;
  tmu_pkg::tex_filter_t    filter;
  tmu_pkg::tex_border_t    border_u, border_v;
  tmu_pkg::tex_addressing_t addressing;
  tmu_pkg::rgba8888_t      border_rgba, map_constant_rgba;
  tmu_pkg::tex_combine_t   map_combine;
  // The control port: the current DRF.
  tmu_pkg::drf_op_t        op;
  tmu_pkg::drf_index_t     link;
  logic                    takes_coords, footprint, detail;
  tmu_pkg::probe_log2_t    log2_max_probes;
  tmu_pkg::q_rule_t        q_rule;
  tmu_pkg::tex_detail_combine_t detail_combine;
  tmu_pkg::tex_border_t    ctl_border_u, ctl_border_v;
  tmu_pkg::tex_combine_t   combine;
  tmu_pkg::rgba8888_t      constant_rgba;
  logic [tmu_pkg::Drfs*LinkW-1:0] links;

  tmu_texram_drf_file u_drf_file (
    .clk_i, .rst_ni,
    .wr_en_i              (drf_fire),
    .wr_drf_i             (drf_drf_i),
    .wr_field_i           (drf_field_i),
    .wr_value_i           (drf_value_i),
    .rd_drf_i             (map_drf),
    .rd_face_i            (face_q),
    .rd_own_base_i        (map_own_base),
    .rd_base_o            (base),
    .rd_log2_w_o          (log2_w),
    .rd_log2_h_o          (log2_h),
    .rd_kind_o            (kind),
    .rd_single_channel_o  (single_channel),
    .rd_filter_o          (filter),
    .rd_border_u_o        (border_u),
    .rd_border_v_o        (border_v),
    .rd_addressing_o      (addressing),
    .rd_border_rgba_o     (border_rgba),
    .rd_constant_rgba_o   (map_constant_rgba),
    .rd_combine_o         (map_combine),
    .ctl_drf_i            (num_q),
    .ctl_op_o             (op),
    .ctl_link_o           (link),
    .ctl_takes_coords_o   (takes_coords),
    .ctl_footprint_o      (footprint),
    .ctl_log2_max_probes_o(log2_max_probes),
    .ctl_q_rule_o         (q_rule),
    .ctl_detail_o         (detail),
    .ctl_detail_combine_o (detail_combine),
    .ctl_border_u_o       (ctl_border_u),
    .ctl_border_v_o       (ctl_border_v),
    .ctl_combine_o        (combine),
    .ctl_constant_rgba_o  (constant_rgba),
    .links_o              (links)
  );

  // DRF n's link; 0 for n = 0 (no DRF).
  function automatic tmu_pkg::drf_index_t link_of(tmu_pkg::drf_index_t n);
    link_of = n == '0 ? '0 : links[(32'(n) - 1)*LinkW +: LinkW];
  endfunction

  // A detail map's offsets DRF (the link) and detail DRF (its link), and where the chain goes
  // on: past both when they exist (golden next_drf).
  tmu_pkg::drf_index_t offsets_drf, detail_drf, next_drf;
  logic                skip_detail;
  assign offsets_drf = link;
  assign detail_drf  = link_of(link);
  assign skip_detail = detail && offsets_drf != '0 && detail_drf != '0;
  assign next_drf    = skip_detail ? link_of(detail_drf) : link;

  // ---- The step: the current DRF's sample -----------------------------------------------------

  logic               step_req_valid, step_req_ready, step_out_valid, step_out_ready;
  // While streaming the unit takes the parameter itself; else the pixel's registers.
  logic               streaming;
  tmu_pkg::tex_coord_t step_u, step_v;
  tmu_pkg::lod_t      step_lambda;
  tmu_pkg::rgba8888_t step_shade;
  tmu_pkg::tex_deriv_t step_r1u, step_r1v, step_r2u, step_r2v;
  assign streaming   = state_q == StStream;
  assign step_u      = streaming ? param_u_i : u_q;
  assign step_v      = streaming ? param_v_i : v_q;
  assign step_lambda = streaming ? param_lambda_i : lambda_q;
  assign step_shade  = streaming ? param_shade_i : shade_q;
  assign step_r1u    = streaming ? param_r1u_i : r1u_q;
  assign step_r1v    = streaming ? param_r1v_i : r1v_q;
  assign step_r2u    = streaming ? param_r2u_i : r2u_q;
  assign step_r2v    = streaming ? param_r2v_i : r2v_q;
  logic               step_clut_ready;
  tmu_pkg::rgba8888_t step_rgba;

  tmu_texram_step u_step (
    .clk_i, .rst_ni,
    .t_i                  (num_q),
    .o_i                  (offsets_drf),
    .d_i                  (detail_drf),
    .footprint_i          (footprint),
    .log2_max_probes_i    (log2_max_probes),
    .q_rule_i             (q_rule),
    .detail_i             (detail),
    .detail_combine_i     (detail_combine),
    .border_u_i           (ctl_border_u),
    .border_v_i           (ctl_border_v),
    .combine_i            (combine),
    .constant_rgba_i      (constant_rgba),
    .map_drf_o            (map_drf),
    .map_own_base_o       (map_own_base),
    .map_base_i           (base),
    .map_log2_w_i         (log2_w),
    .map_log2_h_i         (log2_h),
    .map_kind_i           (kind),
    .map_single_channel_i (single_channel),
    .map_filter_i         (filter),
    .map_border_u_i       (border_u),
    .map_border_v_i       (border_v),
    .map_addressing_i     (addressing),
    .map_border_rgba_i    (border_rgba),
    .map_constant_rgba_i  (map_constant_rgba),
    .map_combine_i        (map_combine),
    .clut_valid_i         (clut_valid_i && state_q == StIdle),
    .clut_ready_o         (step_clut_ready),
    .clut_addr_i,
    .clut_rgba_i,
    .req_valid_i          (step_req_valid),
    .req_ready_o          (step_req_ready),
    .req_u_i              (step_u),
    .req_v_i              (step_v),
    .req_lambda_i         (step_lambda),
    .req_shade_i          (step_shade),
    .req_r1u_i            (step_r1u),
    .req_r1v_i            (step_r1v),
    .req_r2u_i            (step_r2u),
    .req_r2v_i            (step_r2v),
    .mem_req_valid_o,
    .mem_req_ready_i,
    .mem_req_en_o,
    .mem_req_addr_o,
    .mem_resp_valid_i,
    .mem_resp_data_i,
    .out_valid_o          (step_out_valid),
    .out_ready_i          (step_out_ready),
    .out_rgba_o           (step_rgba)
  );

  // ---- eq. 6-7: C = min(255, C_d + R E / 255) --------------------------------------------------

  logic               spec_in_valid, spec_in_ready, spec_out_valid, spec_out_ready;
  tmu_pkg::rgba8888_t spec_colour;

  tmu_specular_combine u_specular_combine (
    .clk_i, .rst_ni,
    .in_valid_i      (spec_in_valid),
    .in_ready_o      (spec_in_ready),
    .in_diffuse_i    (colour_q),
    .in_specular_i   (env_q),
    .in_reflectance_i(refl_q),
    .out_valid_o     (spec_out_valid),
    .out_ready_i     (spec_out_ready),
    .out_colour_o    (spec_colour)
  );

  // ---- Handshakes ----------------------------------------------------------------------------

  logic out_free;  // the output register can load at this edge
  assign out_free = !out_valid_q || out_ready_i;

  // The current DRF streams (see the header); a streamed parameter goes into the unit now.
  logic streamable, stream_take;
  assign streamable  = (op == OpTexture || op == OpEmit) && link == '0 && !detail &&
                       32'(num_q) != tmu_pkg::Drfs;
  assign stream_take = streaming && param_valid_i && param_lead_i == num_q &&
                       32'(in_flight_q) < MaxInFlight;

  assign drf_ready_o   = state_q == StIdle;
  assign clut_ready_o  = state_q == StIdle && step_clut_ready;
  assign param_ready_o = state_q == StIdle || state_q == StParam || (stream_take && step_req_ready);
  assign drf_fire      = drf_valid_i && drf_ready_o;
  assign clut_fire     = clut_valid_i && clut_ready_o;
  assign param_fire    = param_valid_i && param_ready_o;

  assign step_req_valid = state_q == StIssue || stream_take;
  assign step_out_ready = (state_q == StWait && (op != OpEmit || out_free)) ||
                          (streaming && out_free && !colour_due_q);
  assign spec_in_valid  = state_q == StFinish && have_env_q;
  assign spec_out_ready = state_q == StCombine && out_free;

  // ---- The sequencer -------------------------------------------------------------------------

  always_comb begin
    state_d     = state_q;
    num_d       = num_q;
    step_d      = step_q;
    u_d         = u_q;
    v_d         = v_q;
    lambda_d    = lambda_q;
    face_d      = face_q;
    r1u_d       = r1u_q;
    r1v_d       = r1v_q;
    r2u_d       = r2u_q;
    r2v_d       = r2v_q;
    shade_d     = shade_q;
    colour_d    = colour_q;
    refl_d      = refl_q;
    env_d       = env_q;
    have_refl_d = have_refl_q;
    have_env_d  = have_env_q;
    shaded_d    = shaded_q;
    out_valid_d = out_valid_q && !out_ready_i;
    out_rgba_d  = out_rgba_q;
    out_last_d  = out_last_q;
    pixels_d    = pixels_q;
    params_d    = params_q;
    steps_d     = steps_q;
    limit_d     = limit_q;
    in_flight_d = in_flight_q;
    colour_due_d = colour_due_q;

    if (param_fire) begin  // a parameter's coordinates (the first's shade and lead below)
      u_d      = param_u_i;
      v_d      = param_v_i;
      lambda_d = param_lambda_i;
      face_d   = param_face_i;
      r1u_d    = param_r1u_i;
      r1v_d    = param_r1v_i;
      r2u_d    = param_r2u_i;
      r2v_d    = param_r2v_i;
      params_d = params_q + 1'b1;
    end

    unique case (state_q)
      StIdle: begin
        if (param_fire) begin
          num_d       = param_lead_i;
          step_d      = '0;
          shade_d     = param_shade_i;
          colour_d    = '0;
          refl_d      = '0;
          env_d       = '0;
          have_refl_d = 1'b0;
          have_env_d  = 1'b0;
          shaded_d    = 1'b0;
          pixels_d    = pixels_q + 1'b1;
          state_d     = StCheck;
        end
      end
      StCheck: begin
        if (num_q == '0) begin
          state_d = StFinish;
        end else if (32'(step_q) >= MaxSteps) begin
          limit_d = 1'b1;
          state_d = StFinish;
        end else if (step_q != '0 && takes_coords) begin
          state_d = StParam;
        end else begin
          state_d = StIssue;
        end
      end
      StParam: begin
        if (param_fire) begin
          if (op == OpTexture && !shaded_q) shade_d = param_shade_i;
          state_d = StIssue;
        end
      end
      StIssue: begin
        if (step_req_ready) begin
          steps_d = steps_q + 1'b1;
          state_d = StWait;
          // The pixel's only step, a streamable one: the next pixels may follow it into the unit.
          if (step_q == '0 && streamable) begin
            in_flight_d = InFlightW'(1);
            state_d     = StStream;
          end
        end
      end
      StWait: begin
        if (step_out_valid && step_out_ready) begin
          unique case (op)
            OpTexture: colour_d = step_rgba;
            OpShading: begin
              shade_d  = step_rgba;
              shaded_d = 1'b1;
            end
            OpReflectance: begin
              refl_d      = step_rgba;
              have_refl_d = 1'b1;
            end
            OpEnvironment: begin
              env_d      = step_rgba;
              have_env_d = 1'b1;
              if (!have_refl_q) refl_d = constant_rgba;
            end
            OpEmit: begin
              out_valid_d = 1'b1;
              out_rgba_d  = step_rgba;
              out_last_d  = 1'b0;
            end
            default: ;  // ops 5..7 do nothing
          endcase
          // Past a detail map's offsets and detail DRFs: two more steps (golden next_drf).
          num_d   = next_drf;
          step_d  = step_q + (skip_detail ? 4'd3 : 4'd1);
          if (skip_detail) steps_d = steps_q + tmu_pkg::StatCountW'(2);
          state_d = StCheck;
        end
      end
      StFinish: begin
        if (have_env_q) begin
          if (spec_in_ready) state_d = StCombine;
        end else if (out_free) begin
          out_valid_d = 1'b1;
          out_rgba_d  = colour_q;
          out_last_d  = 1'b1;
          state_d     = StIdle;
        end
      end
      StCombine: begin
        if (spec_out_valid && out_free) begin
          out_valid_d = 1'b1;
          out_rgba_d  = spec_colour;
          out_last_d  = 1'b1;
          state_d     = StIdle;
        end
      end
      StStream: begin
        if (param_fire) begin  // another pixel of the same DRF: its only step issued
          pixels_d = pixels_q + 1'b1;
          steps_d  = steps_q + 1'b1;
        end
        if (step_out_valid && step_out_ready) begin  // a pixel's colour: its sample
          out_valid_d  = 1'b1;
          out_rgba_d   = step_rgba;
          out_last_d   = op != OpEmit;
          colour_due_d = op == OpEmit;
        end else if (colour_due_q && out_free) begin  // an emit's pixel ends: C_d, still 0
          out_valid_d  = 1'b1;
          out_rgba_d   = '0;
          out_last_d   = 1'b1;
          colour_due_d = 1'b0;
        end
        in_flight_d = in_flight_q + InFlightW'(param_fire) -
                      InFlightW'(step_out_valid && step_out_ready);
        // Empty, and the next parameter (if any) is not this DRF's: back to one at a time.
        if (in_flight_d == '0 && !colour_due_d && !stream_take) state_d = StIdle;
      end
      default: state_d = StIdle;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q     <= StIdle;
      num_q       <= '0;
      step_q      <= '0;
      face_q      <= '0;
      have_refl_q <= 1'b0;
      have_env_q  <= 1'b0;
      shaded_q    <= 1'b0;
      out_valid_q <= 1'b0;
      pixels_q    <= '0;
      params_q    <= '0;
      steps_q     <= '0;
      limit_q     <= 1'b0;
      in_flight_q <= '0;
      colour_due_q <= 1'b0;
    end else begin
      state_q     <= state_d;
      num_q       <= num_d;
      step_q      <= step_d;
      face_q      <= face_d;
      have_refl_q <= have_refl_d;
      have_env_q  <= have_env_d;
      shaded_q    <= shaded_d;
      out_valid_q <= out_valid_d;
      pixels_q    <= pixels_d;
      params_q    <= params_d;
      steps_q     <= steps_d;
      limit_q     <= limit_d;
      in_flight_q <= in_flight_d;
      colour_due_q <= colour_due_d;
    end
  end

  // The pixel's data: written before it is read (a pixel's first parameter loads them all).
  always_ff @(posedge clk_i) begin
    u_q        <= u_d;
    v_q        <= v_d;
    r1u_q      <= r1u_d;
    r1v_q      <= r1v_d;
    r2u_q      <= r2u_d;
    r2v_q      <= r2v_d;
    lambda_q   <= lambda_d;
    shade_q    <= shade_d;
    colour_q   <= colour_d;
    refl_q     <= refl_d;
    env_q      <= env_d;
    out_rgba_q <= out_rgba_d;
    out_last_q <= out_last_d;
  end

  assign out_valid_o       = out_valid_q;
  assign out_rgba_o        = out_rgba_q;
  assign out_last_o        = out_last_q;
  assign stat_pixels_o     = pixels_q;
  assign stat_parameters_o = params_q;
  assign stat_steps_o      = steps_q;
  assign stat_step_limit_o = limit_q;

  // clut_fire only feeds the assertion below.
  logic unused_clut_fire;
  assign unused_clut_fire = clut_fire;

`ifndef SYNTHESIS
  // A write is taken only between pixels.
  property p_write_idle;
    @(posedge clk_i) disable iff (!rst_ni) (drf_fire || clut_fire) |-> state_q == StIdle;
  endproperty
  a_write_idle: assert property (p_write_idle);
`endif

endmodule
