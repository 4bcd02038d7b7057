/// The clip-map address unit (003) on the TEXRAM's sampling path, bit-exact with golden
/// clipmap::sample (golden/clipmap/clipmap.hpp, the specification: the clip stack's layout, the
/// two substitution rules, the load port). A request carries virtual coordinates (u, v:
/// texels of the virtual level 0, up to 32k) and lambda; the unit reads a clip-map (a tile of
/// 2^t x 2^t texels for each of the C = V - t finest levels, the levels from C up whole) and
/// filters as the trilinear unit does, with the same access and colour stages
/// (tmu_texram_access).
///
/// Pipeline (each stage a register with valid; one request per clock while nothing stalls):
///   S1 request  lambda -> levels and level weight (tmu_trilinear_lod), taken with the request
///   S2 hold     per clipped level, whether its tile holds the sample point's taps
///               (tmu_clip_hold, one per level); per-sample substitution: the sample is held
///               when every level it reads holds it, else lambda is raised to the first level
///               above its first whose tile holds the point (a whole level always does), and
///               the levels are chosen again (a second tmu_trilinear_lod)
///   S3 axes     per level and axis: first tap and weight (tmu_trilinear_axis)
///   S4 taps     per tap: the virtual texture's border operator (tmu_trilinear_border on a side
///               of 2^(V - l)): the virtual texel, or outside
///   S5 subst.   per tap: per-tap substitution (tmu_clip_tap): the first coarser level whose
///               tile holds the texel, and the texel there
///   S6 address  per tap: the toroidal stored position, bank and cell (tmu_clip_address, the
///               level offsets from tmu_clip_offsets); the counters
///   then tmu_texram_access: the access (the lowest tap decides a bank's cell), the in-flight
///   buffer, texels, CLUT, blend and eq. 5.
/// The output is valid 14 cycles after the request was accepted (page hit).
///
/// Writes: the CLUT (clut), a clipped level's valid region (region: level, x0, y0, x1, y1;
/// registers, empty after reset; a write to a level beyond the register sets is ignored) and a
/// texel of the clip-map (load: level, virtual x, y, the texel's bytes). Each is taken only
/// while no sample is between the request port and the texel stage (the ready stays low
/// meanwhile), so it is ordered after every sample before it and before every sample after
/// it; a request offered with a write in one cycle is taken too and comes after it. A load
/// writes its texel at the toroidal place (every replica of a 1 x 1 level) through the memory
/// port, one access per byte plane with we set; a load to a level beyond the top writes
/// nothing. While a load writes, the access stage waits for the port.
///
/// Counters: wayward_samples (a substitution served the sample), substituted_taps (taps read
/// from a coarser level), conflicts (taps that wanted another cell of a bank a lower tap took;
/// only when the regions are not nested), each counted when the sample leaves S6.
///
/// Configuration (cfg_*): quasi-static, held while the unit is busy; encodings are golden's
/// (texram::TexelKind without CCC, Filter, Border, Combine; clipmap::Substitution).
///
/// Example: V = 8, t = 5, per sample, the eye at (128, 128): the tiles of levels 0, 1, 2 are
/// [112, 144)^2, [48, 80)^2 and [16, 48)^2. u = v = 180.0, lambda = 0.5 reads levels 0 and 1;
/// level 0's tile does not hold the point's taps (179, 180), level 1's does not hold (89, 90),
/// level 2's holds (44, 45): lambda is raised to 2, level 2 is read alone.
module tmu_clipmap #(
  /// Filter and level weight bits (golden Widths::weight), the port fractions elsewhere.
  parameter int unsigned WeightBits = 8
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  /// The clip-map: log2 of the virtual side V (2..15) and of the tile t (2..10, t <= V); the
  /// texel kind (luminance, index, true colour, single), the single component's channel, the
  /// filter, the border operator of the virtual texture per axis and its colour, eq. 5, and the
  /// substitution rule (0 per sample, 1 per tap).
  input  tmu_pkg::clip_log2_t        cfg_log2_virtual_i,
  input  tmu_pkg::mip_log2_t         cfg_log2_tile_i,
  input  tmu_pkg::tex_kind_t         cfg_kind_i,
  input  tmu_pkg::byte_plane_t       cfg_single_channel_i,
  input  tmu_pkg::tex_filter_t       cfg_filter_i,
  input  tmu_pkg::tex_border_t       cfg_border_u_i,
  input  tmu_pkg::tex_border_t       cfg_border_v_i,
  input  tmu_pkg::rgba8888_t         cfg_border_rgba_i,
  input  tmu_pkg::tex_combine_t      cfg_combine_i,
  input  tmu_pkg::rgba8888_t         cfg_constant_rgba_i,
  input  tmu_pkg::clip_substitution_t cfg_substitution_i,

  /// CLUT write.
  input  logic                       clut_valid_i,
  output logic                       clut_ready_o,
  input  tmu_pkg::clut_index_t       clut_addr_i,
  input  tmu_pkg::rgba8888_t         clut_rgba_i,

  /// Region write: the texels [x0, x1) x [y0, y1) that level's tile holds.
  input  logic                       region_valid_i,
  output logic                       region_ready_o,
  input  tmu_pkg::mip_level_t        region_level_i,
  input  tmu_pkg::clip_bound_t       region_x0_i,
  input  tmu_pkg::clip_bound_t       region_y0_i,
  input  tmu_pkg::clip_bound_t       region_x1_i,
  input  tmu_pkg::clip_bound_t       region_y1_i,

  /// Load: the texel (x, y) of a level, its bytes (plane p in byte 3 - p).
  input  logic                       load_valid_i,
  output logic                       load_ready_o,
  input  tmu_pkg::mip_level_t        load_level_i,
  input  tmu_pkg::clip_coord_t       load_x_i,
  input  tmu_pkg::clip_coord_t       load_y_i,
  input  tmu_pkg::rgba8888_t         load_texel_i,

  /// Sample request.
  input  logic                       req_valid_i,
  output logic                       req_ready_o,
  input  tmu_pkg::tex_coord_t        req_u_i,
  input  tmu_pkg::tex_coord_t        req_v_i,
  input  tmu_pkg::lod_t              req_lambda_i,
  input  tmu_pkg::rgba8888_t         req_shade_i,

  /// Memory access: reads (we low) and the loads' writes (we high, the bytes in wdata); a bank
  /// left out shows address 0 + plane on a read, 0 and data 0 on a write. Reads are answered
  /// in order, writes are not.
  output logic                       mem_req_valid_o,
  input  logic                       mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]  mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  output logic                       mem_req_we_o,
  output logic [tmu_pkg::Banks*8-1:0] mem_req_wdata_o,
  input  logic                       mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0] mem_resp_data_i,

  /// The sample, RGBA8888, in order.
  output logic                       out_valid_o,
  input  logic                       out_ready_i,
  output tmu_pkg::rgba8888_t         out_rgba_o,

  /// Counters (wrap).
  output tmu_pkg::stat_count_t       stat_wayward_samples_o,
  output tmu_pkg::stat_count_t       stat_substituted_taps_o,
  output tmu_pkg::stat_count_t       stat_conflicts_o
);

  localparam int unsigned W       = WeightBits;
  localparam int unsigned Banks   = tmu_pkg::Banks;
  localparam int unsigned Taps    = 8;
  localparam int unsigned AddrW   = tmu_pkg::BankAddrW;
  localparam int unsigned CoordW  = tmu_pkg::ClipCoordW;  // 15
  localparam int unsigned LW      = tmu_pkg::MipLevelW;
  localparam int unsigned TapW    = 18;
  localparam int unsigned Clipped = 13;  // region sets: levels 0..12 (V <= 15, t >= 2)
  localparam int unsigned Levels  = 16;
  localparam int unsigned CW      = tmu_pkg::Rgba8888W;
  localparam int unsigned InfoW   = Taps * 8 + 5 * W + CW;

  localparam tmu_pkg::tex_kind_t   KindIndex = 3'd1, KindTrueColour = 3'd2, KindSingle = 3'd3;
  localparam tmu_pkg::tex_filter_t FilterNearest = 2'd0, FilterTrilinear = 2'd2;
  localparam tmu_pkg::tex_border_t BorderClamp = 2'd1, BorderColour = 2'd2, BorderMirror = 2'd3;
  localparam tmu_pkg::tex_combine_t CombineConstant = 2'd1, CombineShade = 2'd2;

  if (Banks != 8 || CoordW != 15 || LW != 4) begin : gen_check
    $error("tmu_clipmap: built for 8 banks, 15-bit virtual coordinates and 4-bit levels");
  end

  // ---- Configuration, decoded ---------------------------------------------------------------

  logic                nearest, trilinear, per_tap, four_planes;
  logic                clamp_u, border_u, mirror_u, clamp_v, border_v, mirror_v;
  tmu_pkg::mip_level_t clipped;  // C
  assign nearest     = cfg_filter_i == FilterNearest;
  assign trilinear   = cfg_filter_i == FilterTrilinear;
  assign per_tap     = cfg_substitution_i != '0;
  assign four_planes = cfg_kind_i == KindTrueColour;
  assign clamp_u     = cfg_border_u_i == BorderClamp;
  assign border_u    = cfg_border_u_i == BorderColour;
  assign mirror_u    = cfg_border_u_i == BorderMirror;
  assign clamp_v     = cfg_border_v_i == BorderClamp;
  assign border_v    = cfg_border_v_i == BorderColour;
  assign mirror_v    = cfg_border_v_i == BorderMirror;
  assign clipped     = LW'(cfg_log2_virtual_i) - LW'(cfg_log2_tile_i);

  logic [Levels*AddrW-1:0] offsets;  // level l's at [l * AddrW +: AddrW]
  tmu_clip_offsets #(.Levels(Levels)) u_offsets (
    .log2_virtual_i(cfg_log2_virtual_i),
    .log2_tile_i   (cfg_log2_tile_i),
    .offset_o      (offsets)
  );

  // ---- Region registers ---------------------------------------------------------------------

  // Level l's x0, y0, x1, y1 at field 4 l + k (k = 0..3), ClipBound bits each.
  localparam int unsigned BW = tmu_pkg::ClipBoundW;
  logic [4*Clipped*BW-1:0] region_q;

  // ---- Pipeline control -------------------------------------------------------------------

  logic s1_valid_q, s2_valid_q, s3_valid_q, s4_valid_q, s5_valid_q, s6_valid_q;
  logic s1_ready, s2_ready, s3_ready, s4_ready, s5_ready, s6_ready;
  logic s2_load, s3_load, s4_load, s5_load, s6_load;
  logic acc_ready, acc_busy, load_busy_q, req_fire, front_busy, quiet;

  assign front_busy  = s1_valid_q || s2_valid_q || s3_valid_q || s4_valid_q || s5_valid_q ||
                       s6_valid_q;
  assign quiet       = !front_busy && !acc_busy && !load_busy_q;
  assign clut_ready_o   = quiet;
  assign region_ready_o = quiet;
  assign load_ready_o   = quiet;
  assign req_ready_o    = s1_ready;
  assign req_fire       = req_valid_i && req_ready_o;

  assign s6_ready = !s6_valid_q || acc_ready;
  assign s5_ready = !s5_valid_q || s6_ready;
  assign s4_ready = !s4_valid_q || s5_ready;
  assign s3_ready = !s3_valid_q || s4_ready;
  assign s2_ready = !s2_valid_q || s3_ready;
  assign s1_ready = !s1_valid_q || s2_ready;
  assign s2_load  = s1_valid_q && s2_ready;
  assign s3_load  = s2_valid_q && s3_ready;
  assign s4_load  = s3_valid_q && s4_ready;
  assign s5_load  = s4_valid_q && s5_ready;
  assign s6_load  = s5_valid_q && s6_ready;

  // ---- S1: request and levels ---------------------------------------------------------------

  tmu_pkg::mip_level_t lod_level0, lod_level1;
  logic [W-1:0]        lod_weight;
  logic                lod_two;

  tmu_trilinear_lod #(.WeightBits(W)) u_lod (
    .lambda_i     (req_lambda_i),
    .top_i        (tmu_pkg::MipLog2W'(cfg_log2_virtual_i)),
    .trilinear_i  (trilinear),
    .level0_o     (lod_level0),
    .level1_o     (lod_level1),
    .weight_o     (lod_weight),
    .two_levels_o (lod_two)
  );

  tmu_pkg::tex_coord_t s1_u_q, s1_v_q;
  tmu_pkg::rgba8888_t  s1_shade_q;
  tmu_pkg::mip_level_t s1_level0_q, s1_level1_q;
  logic [W-1:0]        s1_wl_q;
  logic                s1_two_q;

  // ---- S2: tiles that hold the point; per-sample substitution -------------------------------

  logic [Levels-1:0] holds;  // a whole level (>= C) always holds
  for (genvar m = 0; m < Levels; m++) begin : gen_hold
    if (m < Clipped) begin : gen_clipped
      logic tile_holds;
      tmu_clip_hold #(.Level(m)) u_hold (
        .u_i(s1_u_q), .v_i(s1_v_q), .nearest_i(nearest), .log2_virtual_i(cfg_log2_virtual_i),
        .clamp_u_i(clamp_u), .border_u_i(border_u), .mirror_u_i(mirror_u),
        .clamp_v_i(clamp_v), .border_v_i(border_v), .mirror_v_i(mirror_v),
        .x0_i(region_q[4*m*BW +: BW]), .y0_i(region_q[(4*m + 1)*BW +: BW]),
        .x1_i(region_q[(4*m + 2)*BW +: BW]), .y1_i(region_q[(4*m + 3)*BW +: BW]),
        .holds_o(tile_holds)
      );
      assign holds[m] = LW'(m) >= clipped || tile_holds;
    end else begin : gen_whole
      assign holds[m] = 1'b1;
    end
  end

  logic                held, raise;
  tmu_pkg::mip_level_t raised_level;
  always_comb begin
    held = holds[s1_level0_q] && (!s1_two_q || holds[s1_level1_q]);
    raised_level = s1_level0_q;
    for (int m = Levels - 1; m >= 0; m--) begin
      if (holds[m] && LW'(m) > s1_level0_q) raised_level = LW'(m);
    end
    raise = !per_tap && !held;
  end

  tmu_pkg::mip_level_t sub_level0, sub_level1;
  logic [W-1:0]        sub_weight;
  logic                sub_two;
  tmu_trilinear_lod #(.WeightBits(W)) u_raised_lod (
    .lambda_i     (tmu_pkg::LodW'({raised_level, 8'h00})),
    .top_i        (tmu_pkg::MipLog2W'(cfg_log2_virtual_i)),
    .trilinear_i  (trilinear),
    .level0_o     (sub_level0),
    .level1_o     (sub_level1),
    .weight_o     (sub_weight),
    .two_levels_o (sub_two)
  );

  tmu_pkg::tex_coord_t s2_u_q, s2_v_q;
  tmu_pkg::rgba8888_t  s2_shade_q;
  tmu_pkg::mip_level_t s2_level0_q, s2_level1_q;
  logic [W-1:0]        s2_wl_q;
  logic                s2_two_q, s2_raised_q;

  // ---- S3: the taps of each axis at each level -----------------------------------------------

  // Index 2 j + a: level j, axis a (0 u, 1 v).
  logic [4*TapW-1:0] axis_t0;
  logic [4*W-1:0]    axis_w;
  for (genvar j = 0; j < 2; j++) begin : gen_axis_level
    for (genvar a = 0; a < 2; a++) begin : gen_axis
      tmu_trilinear_axis #(.WeightBits(W), .TapW(TapW)) u_axis (
        .coord_i   (a == 0 ? s2_u_q : s2_v_q),
        .level_i   (j == 0 ? s2_level0_q : s2_level1_q),
        .nearest_i (nearest),
        .t0_o      (axis_t0[(2*j + a)*TapW +: TapW]),
        .weight_o  (axis_w[(2*j + a)*W +: W])
      );
    end
  end

  logic [4*TapW-1:0]   s3_t0_q;
  logic [4*W-1:0]      s3_w_q;
  tmu_pkg::rgba8888_t  s3_shade_q;
  tmu_pkg::mip_level_t s3_level0_q, s3_level1_q;
  logic [W-1:0]        s3_wl_q;
  logic                s3_two_q, s3_raised_q;

  // ---- S4: the virtual texture's border operator ---------------------------------------------

  // Index 4 j + 2 a + i: level j, axis a, tap i (t0 + i).
  logic [8*CoordW-1:0] bord_coord;
  logic [7:0]          bord_outside, bord_parity;
  for (genvar j = 0; j < 2; j++) begin : gen_border_level
    for (genvar a = 0; a < 2; a++) begin : gen_border_axis
      for (genvar i = 0; i < 2; i++) begin : gen_border_tap
        logic [TapW-1:0]   tap;
        logic [CoordW-1:0] stored;  // the pyramid's stored coordinate: not the clip-map's
        logic              unused_stored;
        assign tap = s3_t0_q[(2*j + a)*TapW +: TapW] + TapW'(i);
        tmu_trilinear_border #(.TapW(TapW), .CoordW(CoordW)) u_border (
          .tap_i        (tap),
          .log2_size_i  (tmu_pkg::MipLog2W'(cfg_log2_virtual_i)),
          .level_i      (j == 0 ? s3_level0_q : s3_level1_q),
          .clamp_i      (a == 0 ? clamp_u : clamp_v),
          .border_i     (a == 0 ? border_u : border_v),
          .mirror_i     (a == 0 ? mirror_u : mirror_v),
          .block_grid_i (1'b0),
          .coord_o      (bord_coord[(4*j + 2*a + i)*CoordW +: CoordW]),
          .outside_o    (bord_outside[4*j + 2*a + i]),
          .stored_o     (stored)
        );
        assign unused_stored = ^stored;
        assign bord_parity[4*j + 2*a + i] = tap[0];
      end
    end
  end

  logic [8*CoordW-1:0] s4_coord_q;
  logic [7:0]          s4_outside_q, s4_parity_q;
  logic [4*W-1:0]      s4_w_q;
  tmu_pkg::rgba8888_t  s4_shade_q;
  tmu_pkg::mip_level_t s4_level0_q, s4_level1_q;
  logic [W-1:0]        s4_wl_q;
  logic                s4_two_q, s4_raised_q;

  // ---- S5: per-tap substitution -------------------------------------------------------------

  // Tap t = 4 j + k of level j: k = 0 (x0, y0), 1 (x1, y0), 2 (x0, y1), 3 (x1, y1).
  logic [Taps-1:0]       tap_read, tap_outside, tap_sub, tap_rx, tap_ry;
  tmu_pkg::mip_level_t   tap_level [Taps];
  tmu_pkg::clip_coord_t  tap_x [Taps], tap_y [Taps];

  for (genvar t = 0; t < Taps; t++) begin : gen_subst
    localparam int unsigned J  = t / 4;
    localparam int unsigned XI = 4 * J + (t % 2);
    localparam int unsigned YI = 4 * J + 2 + (t / 2) % 2;
    tmu_pkg::mip_level_t level;
    assign level          = J == 0 ? s4_level0_q : s4_level1_q;
    assign tap_outside[t] = s4_outside_q[XI] || s4_outside_q[YI];
    // Level 1 is read only when it weighs something; nearest reads tap 0 only.
    assign tap_read[t]    = !tap_outside[t] && (J == 0 || s4_two_q) && (t % 4 == 0 || !nearest);
    tmu_clip_tap #(.Levels(Clipped)) u_tap (
      .substitute_i  (per_tap && tap_read[t]),
      .outside_i     (tap_outside[t]),
      .clipped_i     (clipped),
      .level_i       (level),
      .x_i           (s4_coord_q[XI*CoordW +: CoordW]),
      .y_i           (s4_coord_q[YI*CoordW +: CoordW]),
      .region_i      (region_q),
      .level_o       (tap_level[t]),
      .x_o           (tap_x[t]),
      .y_o           (tap_y[t]),
      .substituted_o (tap_sub[t])
    );
    // A 1 x 1 level's replica: the unresolved coordinate's parity, or the substitute's.
    assign tap_rx[t] = tap_sub[t] ? tap_x[t][0] : s4_parity_q[XI];
    assign tap_ry[t] = tap_sub[t] ? tap_y[t][0] : s4_parity_q[YI];
  end

  logic [Taps-1:0]       s5_read_q, s5_outside_q, s5_sub_q, s5_rx_q, s5_ry_q;
  tmu_pkg::mip_level_t   s5_level_q [Taps];
  tmu_pkg::clip_coord_t  s5_x_q [Taps], s5_y_q [Taps];
  logic [4*W-1:0]        s5_w_q;
  tmu_pkg::rgba8888_t    s5_shade_q;
  logic [W-1:0]          s5_wl_q;
  logic                  s5_raised_q;

  // ---- S6: stored positions, banks, cells; counters -----------------------------------------

  logic [Taps*3-1:0]     tap_bank;
  logic [Taps*AddrW-1:0] tap_addr;
  logic [Taps*8-1:0]     tap_info;
  for (genvar t = 0; t < Taps; t++) begin : gen_address
    tmu_pkg::bank_t bank;
    tmu_pkg::bank_addr_t offset;
    always_comb begin
      offset = '0;
      for (int l = 0; l < Levels; l++) begin
        if (LW'(l) == s5_level_q[t]) offset = offsets[l*AddrW +: AddrW];
      end
    end
    tmu_clip_address u_address (
      .log2_virtual_i (cfg_log2_virtual_i),
      .log2_tile_i    (cfg_log2_tile_i),
      .four_planes_i  (four_planes),
      .offset_i       (offset),
      .level_i        (s5_level_q[t]),
      .x_i            (s5_x_q[t]),
      .y_i            (s5_y_q[t]),
      .replica_x_i    (s5_rx_q[t]),
      .replica_y_i    (s5_ry_q[t]),
      .plane_i        ('0),
      .bank_o         (bank),
      .addr_o         (tap_addr[t*AddrW +: AddrW])
    );
    assign tap_bank[t*3 +: 3] = bank;
    assign tap_info[t*8 +: 8] = {s5_outside_q[t], bank, 4'b0000};
  end

  // A conflict: a read tap whose bank a lower read tap took at another cell.
  logic [3:0] conflicts, substituted;
  logic       wayward;
  always_comb begin
    conflicts   = '0;
    substituted = '0;
    for (int t = 0; t < Taps; t++) begin
      logic       found;
      logic [AddrW-1:0] first;
      found = 1'b0;
      first = '0;
      for (int s = 0; s < t; s++) begin
        if (!found && s5_read_q[s] && tap_bank[s*3 +: 3] == tap_bank[t*3 +: 3]) begin
          found = 1'b1;
          first = tap_addr[s*AddrW +: AddrW];
        end
      end
      if (s5_read_q[t] && found && first != tap_addr[t*AddrW +: AddrW]) conflicts = conflicts + 4'd1;
      if (s5_sub_q[t]) substituted = substituted + 4'd1;
    end
    wayward = s5_raised_q || s5_sub_q != '0;
  end

  logic [Taps-1:0]        s6_read_q;
  logic [Taps*3-1:0]      s6_bank_q;
  logic [Taps*AddrW-1:0]  s6_addr_q;
  logic [InfoW-1:0]       s6_info_q;
  tmu_pkg::stat_count_t   wayward_q, substituted_q, conflicts_q;

  // ---- The access and colour stages -----------------------------------------------------------

  logic                                   acc_mem_valid;
  logic [Banks-1:0]                       acc_mem_en;
  logic [Banks*AddrW-1:0]                 acc_mem_addr;

  tmu_texram_access #(.WeightBits(W)) u_access (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .kind_index_i       (cfg_kind_i == KindIndex),
    .kind_true_colour_i (four_planes),
    .kind_single_i      (cfg_kind_i == KindSingle),
    .kind_ccc_i         (1'b0),
    .single_channel_i   (cfg_single_channel_i),
    .border_rgba_i      (cfg_border_rgba_i),
    .combine_constant_i (cfg_combine_i == CombineConstant),
    .combine_shade_i    (cfg_combine_i == CombineShade),
    .constant_rgba_i    (cfg_constant_rgba_i),
    .in_valid_i         (s6_valid_q),
    .in_ready_o         (acc_ready),
    .in_read_i          (s6_read_q),
    .in_bank_i          (s6_bank_q),
    .in_addr_i          (s6_addr_q),
    .in_info_i          (s6_info_q),
    .clut_we_i          (clut_valid_i && clut_ready_o),
    .clut_addr_i        (clut_addr_i),
    .clut_rgba_i        (clut_rgba_i),
    .busy_o             (acc_busy),
    .mem_req_valid_o    (acc_mem_valid),
    .mem_req_ready_i    (mem_req_ready_i && !load_busy_q),
    .mem_req_en_o       (acc_mem_en),
    .mem_req_addr_o     (acc_mem_addr),
    .mem_resp_valid_i   (mem_resp_valid_i),
    .mem_resp_data_i    (mem_resp_data_i),
    .out_valid_o        (out_valid_o),
    .out_ready_i        (out_ready_i),
    .out_rgba_o         (out_rgba_o)
  );

  // ---- The load port's writes -----------------------------------------------------------------

  logic                 load_fire, load_writes, load_last;
  tmu_pkg::bank_t       load_bank;
  tmu_pkg::bank_addr_t  load_cell, load_offset;
  logic [Banks-1:0]     load_en_d;
  logic [Banks-1:0]     load_en_q;
  tmu_pkg::bank_addr_t  load_addr_q;   // plane 0's cell
  tmu_pkg::rgba8888_t   load_texel_q;
  logic [1:0]           load_plane_q;

  assign load_fire   = load_valid_i && load_ready_o;
  // A level beyond the top writes nothing.
  assign load_writes = LW'(load_level_i) <= LW'(cfg_log2_virtual_i);
  always_comb begin
    load_offset = '0;
    for (int l = 0; l < Levels; l++) begin
      if (LW'(l) == load_level_i) load_offset = offsets[l*AddrW +: AddrW];
    end
  end
  tmu_clip_address u_load_address (
    .log2_virtual_i (cfg_log2_virtual_i),
    .log2_tile_i    (cfg_log2_tile_i),
    .four_planes_i  (four_planes),
    .offset_i       (load_offset),
    .level_i        (load_level_i),
    .x_i            (load_x_i),
    .y_i            (load_y_i),
    .replica_x_i    (1'b0),
    .replica_y_i    (1'b0),
    .plane_i        ('0),
    .bank_o         (load_bank),
    .addr_o         (load_cell)
  );
  // The 1 x 1 level (l = V): its four replicas, one cell in each bank of its parity.
  assign load_en_d = LW'(load_level_i) == LW'(cfg_log2_virtual_i)
                   ? (load_level_i[0] ? 8'hF0 : 8'h0F) : 8'(1) << load_bank;
  assign load_last = load_plane_q == (four_planes ? 2'd3 : 2'd0);

  always_comb begin
    mem_req_valid_o = load_busy_q || acc_mem_valid;
    mem_req_we_o    = load_busy_q;
    mem_req_en_o    = load_busy_q ? load_en_q : acc_mem_en;
    mem_req_addr_o  = acc_mem_addr;
    mem_req_wdata_o = '0;
    if (load_busy_q) begin
      for (int b = 0; b < Banks; b++) begin
        mem_req_addr_o[b*AddrW +: AddrW] = load_en_q[b] ? load_addr_q + AddrW'(load_plane_q) : '0;
        // Plane p is byte 3 - p of the texel.
        mem_req_wdata_o[b*8 +: 8] = load_en_q[b] ? load_texel_q[{~load_plane_q, 3'b000} +: 8] : '0;
      end
    end
  end

  // ---- Flops --------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_valid_q    <= 1'b0;
      s2_valid_q    <= 1'b0;
      s3_valid_q    <= 1'b0;
      s4_valid_q    <= 1'b0;
      s5_valid_q    <= 1'b0;
      s6_valid_q    <= 1'b0;
      load_busy_q   <= 1'b0;
      load_plane_q  <= 2'd0;
      wayward_q     <= '0;
      substituted_q <= '0;
      conflicts_q   <= '0;
      region_q      <= '0;
    end else begin
      s1_valid_q <= req_fire || (s1_valid_q && !s2_ready);
      s2_valid_q <= s2_load || (s2_valid_q && !s3_ready);
      s3_valid_q <= s3_load || (s3_valid_q && !s4_ready);
      s4_valid_q <= s4_load || (s4_valid_q && !s5_ready);
      s5_valid_q <= s5_load || (s5_valid_q && !s6_ready);
      s6_valid_q <= s6_load || (s6_valid_q && !acc_ready);
      if (region_valid_i && region_ready_o && region_level_i < LW'(Clipped)) begin
        region_q[4*region_level_i*BW +: 4*BW] <= {region_y1_i, region_x1_i, region_y0_i, region_x0_i};
      end
      if (load_fire) begin
        load_busy_q  <= load_writes;
        load_plane_q <= 2'd0;
      end else if (load_busy_q && mem_req_ready_i) begin
        load_busy_q  <= !load_last;
        load_plane_q <= load_plane_q + 2'd1;
      end
      if (s6_load) begin
        wayward_q     <= wayward_q + tmu_pkg::StatCountW'(wayward);
        substituted_q <= substituted_q + tmu_pkg::StatCountW'(substituted);
        conflicts_q   <= conflicts_q + tmu_pkg::StatCountW'(conflicts);
      end
    end
  end

  // Data registers are read only while their stage is valid (or a load writes): no reset.
  always_ff @(posedge clk_i) begin
    if (load_fire) begin
      load_en_q    <= load_en_d;
      load_addr_q  <= load_cell;
      load_texel_q <= load_texel_i;
    end
    if (req_fire) begin
      s1_u_q      <= req_u_i;
      s1_v_q      <= req_v_i;
      s1_shade_q  <= req_shade_i;
      s1_level0_q <= lod_level0;
      s1_level1_q <= lod_level1;
      s1_wl_q     <= lod_weight;
      s1_two_q    <= lod_two;
    end
    if (s2_load) begin
      s2_u_q      <= s1_u_q;
      s2_v_q      <= s1_v_q;
      s2_shade_q  <= s1_shade_q;
      s2_level0_q <= raise ? sub_level0 : s1_level0_q;
      s2_level1_q <= raise ? sub_level1 : s1_level1_q;
      s2_wl_q     <= raise ? sub_weight : s1_wl_q;
      s2_two_q    <= raise ? sub_two : s1_two_q;
      s2_raised_q <= raise;
    end
    if (s3_load) begin
      s3_t0_q     <= axis_t0;
      s3_w_q      <= axis_w;
      s3_shade_q  <= s2_shade_q;
      s3_level0_q <= s2_level0_q;
      s3_level1_q <= s2_level1_q;
      s3_wl_q     <= s2_wl_q;
      s3_two_q    <= s2_two_q;
      s3_raised_q <= s2_raised_q;
    end
    if (s4_load) begin
      s4_coord_q   <= bord_coord;
      s4_outside_q <= bord_outside;
      s4_parity_q  <= bord_parity;
      s4_w_q       <= s3_w_q;
      s4_shade_q   <= s3_shade_q;
      s4_level0_q  <= s3_level0_q;
      s4_level1_q  <= s3_level1_q;
      s4_wl_q      <= s3_wl_q;
      s4_two_q     <= s3_two_q;
      s4_raised_q  <= s3_raised_q;
    end
    if (s5_load) begin
      s5_read_q    <= tap_read;
      s5_outside_q <= tap_outside;
      s5_sub_q     <= tap_sub;
      s5_rx_q      <= tap_rx;
      s5_ry_q      <= tap_ry;
      for (int t = 0; t < Taps; t++) begin
        s5_level_q[t] <= tap_level[t];
        s5_x_q[t]     <= tap_x[t];
        s5_y_q[t]     <= tap_y[t];
      end
      s5_w_q       <= s4_w_q;
      s5_shade_q   <= s4_shade_q;
      s5_wl_q      <= s4_wl_q;
      s5_raised_q  <= s4_raised_q;
    end
    if (s6_load) begin
      s6_read_q <= s5_read_q;
      s6_bank_q <= tap_bank;
      s6_addr_q <= tap_addr;
      // wx and wy of each level from the axis weights (index 2 j + a).
      s6_info_q <= {s5_shade_q, s5_wl_q, s5_w_q[3*W +: W], s5_w_q[1*W +: W],
                    s5_w_q[2*W +: W], s5_w_q[0*W +: W], tap_info};
    end
  end

  assign stat_wayward_samples_o  = wayward_q;
  assign stat_substituted_taps_o = substituted_q;
  assign stat_conflicts_o        = conflicts_q;

`ifndef SYNTHESIS
  // The configuration is held: a change while the unit is busy is a misuse.
  property p_cfg_stable;
    @(posedge clk_i) disable iff (!rst_ni)
      !quiet |=> ($stable(cfg_log2_virtual_i) && $stable(cfg_log2_tile_i) &&
                  $stable(cfg_kind_i) && $stable(cfg_filter_i) && $stable(cfg_substitution_i));
  endproperty
  a_cfg_stable: assert property (p_cfg_stable);
`endif

endmodule
