/// The TEXRAM's trilinear unit (000 §2, §5, §6; Fig. 8: address and control 812, banks 810,
/// CLUT 814, tri-linear interpolator 818, output and combination stage 820), bit-exact with
/// the golden model texram::sample (golden/texram/trilinear.hpp, the specification: levels,
/// weights, border operators, taps, the bank access, texel kinds, blend and combine).
///
/// A request (u, v: SQ16.8 texels of level 0; lambda: SQ6.8; the shaded intensity I_d) picks
/// one level (nearest, bilinear) or two (trilinear), 1 or 4 taps per level, resolves every
/// tap with the border operator of its axis, and reads the taps' cells in one access of the
/// eight banks per byte plane (4 planes for true colour and CCC: plane p at address + p, in
/// plane order). Each bank is read at most once per access: the layout puts the 2 x 2 taps
/// of each of two adjacent levels in eight different banks (Fig. 2), taps sharing a cell
/// share its read, a tap outside the texture (border mode) reads nothing, a level of weight
/// 0 is not read, and a sample with nothing to read makes no access. Addresses are computed
/// locally (tmu_bank_address, exactly texram::Geometry::cell). The bytes become colours
/// (luminance, single component, true colour; index and CCC through the eight-port CLUT),
/// the colours are blended exactly and rounded once, and combined with eq. 5.
///
/// Pipeline (each stage a register with valid; a stage loads when it is empty or passes its
/// sample on):
///   S1 request  lambda -> levels and level weight (tmu_trilinear_lod), taken with the request;
///               the coordinates as texels (tmu_trilinear_sphere for a sphere map's uN, vN)
///   S2 axes     per level and axis: first tap and weight (tmu_trilinear_axis)
///   S3 taps     per level, axis and tap: border operator, stored coordinate
///               (tmu_trilinear_border)
///   S4 address per tap: bank and address (tmu_bank_address, alone in its stage: its level
///               offset sum is the deepest logic of the unit)
///   then tmu_texram_access, shared with the clip-map unit:
///   S5 issue    per bank: read enable and address (the taps' cells, shared ones once).
///               Drives the memory request from registers: one access per plane, plane p
///               at address + p. Each sample takes an entry of the in-flight buffer
///               (InFlight entries: its tap and weight information) when its first access
///               is accepted (at once when it has nothing to read); no entry free: it waits.
///   memory      the access's response (request order, no ready) is written into the entry:
///               planes 0..2 are gathered, the last completes the entry
///   T  texel    the oldest complete entry: per tap, its bank's bytes -> colour or CLUT
///               index (tmu_trilinear_texel); the eight CLUT reads (tmu_trilinear_clut)
///   X, Y, Z, O  the blend and eq. 5 (tmu_trilinear_blend), then the output register
/// Latency with a page hit (memory response the cycle after the access is accepted): the
/// output is valid 12 cycles after the request was accepted (S1..S5, response, entry, T, X,
/// Y, Z, O). Throughput with out_ready_i high: one sample per clock for 1-plane textures
/// when every access hits (the memory accepts an access per clock); a page fault costs one
/// cycle more (the memory is not ready for a period). 4-plane textures take 4 accesses, 4
/// clocks per sample (+1 per fault). Samples with every tap outside take no access: one
/// per clock. At most InFlight = 4 samples are between issue and the texel stage, enough
/// for one per clock at a response latency of 1 cycle (each holds its entry 2 cycles).
///
/// Configuration (cfg_*): quasi-static, held for the whole run from before reset; encodings
/// are the golden enums' values (texram::TexelKind, Filter, Border, Combine), declared as
/// the enums below (kind_e, filter_e, border_e, combine_e), the one place in the RTL;
/// submodules receive decoded flags.
///
/// The CLUT is a RAM without reset: write every entry before sampling an index or CCC
/// texture. clut_ready_o is high only while no sample is between the request port and the
/// texel stage, so a write is ordered with the samples around it.
///
/// Example: 8 x 8 luminance texture (levels 0..3), trilinear, wrap, u = v = 2.0 (raw
/// 0x200), lambda = 1.5 (raw 0x180): levels 1 and 2, weight 0x80. Level 1 (4 x 4): c = 1.0,
/// taps 0 and 1 with weight 0x80 per axis, banks 4..7; level 2 (2 x 2): c = 0.5, taps 0 and
/// 1 with weight 0 per axis, banks 0..3. One access reads all eight banks.
module tmu_trilinear #(
  /// Fraction bits of a coordinate within a level (golden Widths::sub_texel), 1..8.
  parameter int unsigned SubTexelBits = 8,
  /// Filter and level weight bits (Widths::weight), 1..8.
  parameter int unsigned WeightBits   = 8,
  /// Fraction bits of lambda (Widths::lod_frac), 1..8.
  parameter int unsigned LodFracBits  = 8
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  /// Texture: log2 of the level-0 width and height (0..10), texel configuration, the output
  /// channel of a single-component texture (0 R .. 3 A).
  input  tmu_pkg::mip_log2_t         cfg_log2_w_i,
  input  tmu_pkg::mip_log2_t         cfg_log2_h_i,
  input  tmu_pkg::tex_kind_t         cfg_kind_i,
  input  tmu_pkg::byte_plane_t       cfg_single_channel_i,
  /// Filter, border operator per axis, border colour.
  input  tmu_pkg::tex_filter_t       cfg_filter_i,
  input  tmu_pkg::tex_border_t       cfg_border_u_i,
  input  tmu_pkg::tex_border_t       cfg_border_v_i,
  input  tmu_pkg::rgba8888_t         cfg_border_rgba_i,
  /// eq. 5: the selection and the constant k_T.
  input  tmu_pkg::tex_combine_t      cfg_combine_i,
  input  tmu_pkg::rgba8888_t         cfg_constant_rgba_i,
  /// The request's (u, v): texels (0) or a sphere map's (uN, vN) (1, tmu_trilinear_sphere).
  input  tmu_pkg::tex_addressing_t   cfg_addressing_i,

  /// CLUT write: entry clut_addr_i <= clut_rgba_i (ready only while no sample is in flight).
  input  logic                       clut_valid_i,
  output logic                       clut_ready_o,
  input  tmu_pkg::clut_index_t       clut_addr_i,
  input  tmu_pkg::rgba8888_t         clut_rgba_i,

  /// Sample request.
  input  logic                       req_valid_i,
  output logic                       req_ready_o,
  input  tmu_pkg::tex_coord_t        req_u_i,
  input  tmu_pkg::tex_coord_t        req_v_i,
  input  tmu_pkg::lod_t              req_lambda_i,
  input  tmu_pkg::rgba8888_t         req_shade_i,

  /// Memory access: the banks to read (bit b) and their addresses (bank b at
  /// [b * BankAddrW +: BankAddrW]; 0 where not read) ...
  output logic                       mem_req_valid_o,
  input  logic                       mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]  mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  /// ... and its response, in request order, no ready: bank b's byte at [8 b +: 8].
  input  logic                       mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0] mem_resp_data_i,

  /// The sample, RGBA8888, one per request in request order.
  output logic                       out_valid_o,
  input  logic                       out_ready_i,
  output tmu_pkg::rgba8888_t         out_rgba_o
);

  // ---- Encodings and sizes ------------------------------------------------------------------

  typedef enum logic [2:0] {
    KindLuminance  = 3'd0,
    KindIndex      = 3'd1,
    KindTrueColour = 3'd2,
    KindSingle     = 3'd3,
    KindCcc        = 3'd4
  } kind_e;

  typedef enum logic [1:0] {
    FilterNearest   = 2'd0,
    FilterBilinear  = 2'd1,
    FilterTrilinear = 2'd2
  } filter_e;

  typedef enum logic [1:0] {
    BorderWrap   = 2'd0,
    BorderClamp  = 2'd1,
    BorderColour = 2'd2,
    BorderMirror = 2'd3
  } border_e;

  localparam tmu_pkg::tex_addressing_t AddressingSphere = 1'b1;

  typedef enum logic [1:0] {
    CombineOne      = 2'd0,
    CombineConstant = 2'd1,
    CombineShade    = 2'd2
  } combine_e;

  localparam int unsigned W        = WeightBits;
  localparam int unsigned Banks    = tmu_pkg::Banks;      // 8
  localparam int unsigned Taps     = 8;                   // 2 levels x 2 x 2
  localparam int unsigned AddrW    = tmu_pkg::BankAddrW;  // 21
  localparam int unsigned CoordW   = tmu_pkg::MipCoordW;  // 10
  localparam int unsigned CW       = tmu_pkg::Rgba8888W;  // 32
  localparam int unsigned TapW     = 18;                  // unresolved tap coordinate
  localparam int unsigned InFlight = 4;                   // samples between issue and T
  // Per tap in the in-flight buffer: outside, bank, texel within the CCC block (tx, ty).
  localparam int unsigned TapInfoW = 1 + tmu_pkg::BankW + 4;
  // An entry's information: {shade, wl, wy, wx, taps}.
  localparam int unsigned InfoW    = Taps * TapInfoW + 5 * W + CW;  // tmu_texram_access's

  if (SubTexelBits < 1 || SubTexelBits > 8 || WeightBits < 1 || WeightBits > 8 ||
      LodFracBits < 1 || LodFracBits > 8) begin : gen_check_params
    $error("tmu_trilinear: SubTexelBits, WeightBits and LodFracBits must be 1..8");
  end
  if (Banks != 8 || tmu_pkg::Planes != 4 || tmu_pkg::BankW != 3 ||
      tmu_pkg::TexCoordFrac != 8 || tmu_pkg::LodFrac != 8) begin : gen_check_formats
    $error("tmu_trilinear: built for 8 banks, 4 planes and 8 port fraction bits");
  end

  // Decoded configuration.
  logic                kind_index, kind_true_colour, kind_single, kind_ccc, four_planes;
  logic                nearest, trilinear;
  logic                clamp_u, border_u, mirror_u, clamp_v, border_v, mirror_v;
  tmu_pkg::mip_log2_t  top;

  assign kind_index       = cfg_kind_i == KindIndex;
  assign kind_true_colour = cfg_kind_i == KindTrueColour;
  assign kind_single      = cfg_kind_i == KindSingle;
  assign kind_ccc         = cfg_kind_i == KindCcc;
  assign four_planes      = kind_true_colour || kind_ccc;
  assign nearest          = cfg_filter_i == FilterNearest;
  assign trilinear        = cfg_filter_i == FilterTrilinear;
  assign clamp_u          = cfg_border_u_i == BorderClamp;
  assign border_u         = cfg_border_u_i == BorderColour;
  assign mirror_u         = cfg_border_u_i == BorderMirror;
  assign clamp_v          = cfg_border_v_i == BorderClamp;
  assign border_v         = cfg_border_v_i == BorderColour;
  assign mirror_v         = cfg_border_v_i == BorderMirror;
  assign top              = cfg_log2_w_i > cfg_log2_h_i ? cfg_log2_w_i : cfg_log2_h_i;

  // ---- S1: request and levels ---------------------------------------------------------------

  logic                s1_valid_q, s2_valid_q, s3_valid_q, s4_valid_q;
  logic                s1_ready, s2_ready, s3_ready, s4_ready;
  logic                acc_ready, acc_busy, clut_fire;
  logic                req_fire;

  tmu_pkg::tex_coord_t s1_u_q, s1_v_q;
  tmu_pkg::rgba8888_t  s1_shade_q;
  tmu_pkg::mip_level_t s1_level0_q, s1_level1_q;
  logic [W-1:0]        s1_wl_q;
  logic                s1_two_q;

  tmu_pkg::mip_level_t lod_level0, lod_level1;
  logic [W-1:0]        lod_weight;
  logic                lod_two;

  tmu_trilinear_lod #(.LodFracBits(LodFracBits), .WeightBits(W)) u_lod (
    .lambda_i     (req_lambda_i),
    .top_i        (top),
    .trilinear_i  (trilinear),
    .level0_o     (lod_level0),
    .level1_o     (lod_level1),
    .weight_o     (lod_weight),
    .two_levels_o (lod_two)
  );

  assign req_ready_o = s1_ready;
  assign req_fire    = req_valid_i && req_ready_o;

  // The request's coordinates as texels of level 0 (sphere addressing: a sphere map's uN, vN).
  tmu_pkg::tex_coord_t sphere_u, sphere_v, req_u, req_v;

  tmu_trilinear_sphere u_sphere_u (
    .coord_i(req_u_i), .flip_i(1'b0), .log2_i(cfg_log2_w_i), .coord_o(sphere_u)
  );
  tmu_trilinear_sphere u_sphere_v (
    .coord_i(req_v_i), .flip_i(1'b1), .log2_i(cfg_log2_h_i), .coord_o(sphere_v)
  );
  assign req_u = cfg_addressing_i == AddressingSphere ? sphere_u : req_u_i;
  assign req_v = cfg_addressing_i == AddressingSphere ? sphere_v : req_v_i;

  // ---- S2: the taps of each axis at each level -----------------------------------------------

  // Index 2 j + a: level j, axis a (0 u, 1 v).
  logic [4*TapW-1:0]   axis_t0;
  logic [4*W-1:0]      axis_w;

  for (genvar j = 0; j < 2; j++) begin : gen_axis_level
    for (genvar a = 0; a < 2; a++) begin : gen_axis
      tmu_trilinear_axis #(.SubTexelBits(SubTexelBits), .WeightBits(W), .TapW(TapW)) u_axis (
        .coord_i   (a == 0 ? s1_u_q : s1_v_q),
        .level_i   (j == 0 ? s1_level0_q : s1_level1_q),
        .nearest_i (nearest),
        .t0_o      (axis_t0[(2*j + a)*TapW +: TapW]),
        .weight_o  (axis_w[(2*j + a)*W +: W])
      );
    end
  end

  logic [4*TapW-1:0]   s2_t0_q;
  logic [4*W-1:0]      s2_w_q;
  tmu_pkg::rgba8888_t  s2_shade_q;
  tmu_pkg::mip_level_t s2_level0_q, s2_level1_q;
  logic [W-1:0]        s2_wl_q;
  logic                s2_two_q;

  // ---- S3: border operators and stored coordinates --------------------------------------------

  // Index 4 j + 2 a + i: level j, axis a, tap i (t0 + i).
  logic [8*CoordW-1:0] bord_coord, bord_stored;
  logic [7:0]          bord_outside;

  for (genvar j = 0; j < 2; j++) begin : gen_border_level
    for (genvar a = 0; a < 2; a++) begin : gen_border_axis
      for (genvar i = 0; i < 2; i++) begin : gen_border_tap
        tmu_trilinear_border #(.TapW(TapW)) u_border (
          .tap_i        (s2_t0_q[(2*j + a)*TapW +: TapW] + TapW'(i)),
          .log2_size_i  (a == 0 ? cfg_log2_w_i : cfg_log2_h_i),
          .level_i      (j == 0 ? s2_level0_q : s2_level1_q),
          .clamp_i      (a == 0 ? clamp_u : clamp_v),
          .border_i     (a == 0 ? border_u : border_v),
          .mirror_i     (a == 0 ? mirror_u : mirror_v),
          .block_grid_i (kind_ccc),
          .coord_o      (bord_coord[(4*j + 2*a + i)*CoordW +: CoordW]),
          .outside_o    (bord_outside[4*j + 2*a + i]),
          .stored_o     (bord_stored[(4*j + 2*a + i)*CoordW +: CoordW])
        );
      end
    end
  end

  logic [8*CoordW-1:0] s3_stored_q;
  logic [8*2-1:0]      s3_sub_q;  // the coordinates' low 2 bits: the texel in its CCC block
  logic [7:0]          s3_outside_q;
  logic [4*W-1:0]      s3_w_q;
  tmu_pkg::rgba8888_t  s3_shade_q;
  tmu_pkg::mip_level_t s3_level0_q, s3_level1_q;
  logic [W-1:0]        s3_wl_q;
  logic                s3_two_q;

  // ---- S4: banks and addresses --------------------------------------------------------------

  // Tap t = 4 j + k of level j: k = 0 (x0, y0), 1 (x1, y0), 2 (x0, y1), 3 (x1, y1).
  logic [Taps-1:0]       tap_read;
  logic [Taps*3-1:0]     tap_bank;
  logic [Taps*AddrW-1:0] tap_addr;
  logic [Taps*TapInfoW-1:0] tap_info;

  for (genvar t = 0; t < Taps; t++) begin : gen_tap
    localparam int unsigned J  = t / 4;
    localparam int unsigned XI = 4 * J + (t % 2);       // index of the tap's x
    localparam int unsigned YI = 4 * J + 2 + (t / 2) % 2;  // ... and y
    tmu_pkg::mip_coord_t sx, sy;
    tmu_pkg::bank_t      bank;
    logic                outside;

    assign sx      = s3_stored_q[XI*CoordW +: CoordW];
    assign sy      = s3_stored_q[YI*CoordW +: CoordW];
    assign outside = s3_outside_q[XI] || s3_outside_q[YI];
    // Level 1 is read only when it weighs something; nearest reads tap 0 only.
    assign tap_read[t] = !outside && (J == 0 || s3_two_q) && (t % 4 == 0 || !nearest);

    tmu_bank_address u_address (
      .cfg_log2_w_i      (cfg_log2_w_i),
      .cfg_log2_h_i      (cfg_log2_h_i),
      .cfg_four_planes_i (four_planes),
      .cfg_block_grid_i  (kind_ccc),
      .in_level_i        (J == 0 ? s3_level0_q : s3_level1_q),
      .in_x_i            (sx),
      .in_y_i            (sy),
      .in_plane_i        ('0),
      .out_bank_o        (bank),
      .out_addr_o        (tap_addr[t*AddrW +: AddrW])
    );
    assign tap_bank[t*3 +: 3] = bank;
    assign tap_info[t*TapInfoW +: TapInfoW] = {
      outside, bank, s3_sub_q[YI*2 +: 2], s3_sub_q[XI*2 +: 2]};
  end

  logic [Taps-1:0]          s4_read_q;
  logic [Taps*3-1:0]        s4_bank_q;
  logic [Taps*AddrW-1:0]    s4_addr_q;
  logic [InfoW-1:0]         s4_info_q;

  // ---- S5 onward: the access and colour stages ---------------------------------------------

  tmu_texram_access #(.WeightBits(W), .InFlight(InFlight), .FirstTapWins(1'b0)) u_access (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .kind_index_i       (kind_index),
    .kind_true_colour_i (kind_true_colour),
    .kind_single_i      (kind_single),
    .kind_ccc_i         (kind_ccc),
    .single_channel_i   (cfg_single_channel_i),
    .border_rgba_i      (cfg_border_rgba_i),
    .combine_constant_i (cfg_combine_i == CombineConstant),
    .combine_shade_i    (cfg_combine_i == CombineShade),
    .constant_rgba_i    (cfg_constant_rgba_i),
    .in_valid_i         (s4_valid_q),
    .in_ready_o         (acc_ready),
    .in_read_i          (s4_read_q),
    .in_bank_i          (s4_bank_q),
    .in_addr_i          (s4_addr_q),
    .in_info_i          (s4_info_q),
    .clut_we_i          (clut_fire),
    .clut_addr_i        (clut_addr_i),
    .clut_rgba_i        (clut_rgba_i),
    .busy_o             (acc_busy),
    .mem_req_valid_o    (mem_req_valid_o),
    .mem_req_ready_i    (mem_req_ready_i),
    .mem_req_en_o       (mem_req_en_o),
    .mem_req_addr_o     (mem_req_addr_o),
    .mem_resp_valid_i   (mem_resp_valid_i),
    .mem_resp_data_i    (mem_resp_data_i),
    .out_valid_o        (out_valid_o),
    .out_ready_i        (out_ready_i),
    .out_rgba_o         (out_rgba_o)
  );

  // Nothing between the request port and the texel stage: a CLUT write is ordered.
  assign clut_ready_o = !(s1_valid_q || s2_valid_q || s3_valid_q || s4_valid_q) && !acc_busy;
  assign clut_fire    = clut_valid_i && clut_ready_o;

  // ---- Pipeline control -----------------------------------------------------------------------

  assign s4_ready = !s4_valid_q || acc_ready;
  assign s3_ready = !s3_valid_q || s4_ready;
  assign s2_ready = !s2_valid_q || s3_ready;
  assign s1_ready = !s1_valid_q || s2_ready;

  logic s2_load, s3_load, s4_load;
  assign s2_load = s1_valid_q && s2_ready;
  assign s3_load = s2_valid_q && s3_ready;
  assign s4_load = s3_valid_q && s4_ready;

  // ---- Flops --------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_valid_q    <= 1'b0;
      s2_valid_q    <= 1'b0;
      s3_valid_q    <= 1'b0;
      s4_valid_q    <= 1'b0;
    end else begin
      s1_valid_q    <= req_fire || (s1_valid_q && !s2_ready);
      s2_valid_q    <= s2_load || (s2_valid_q && !s3_ready);
      s3_valid_q    <= s3_load || (s3_valid_q && !s4_ready);
      s4_valid_q    <= s4_load || (s4_valid_q && !acc_ready);
    end
  end

  // Data registers are read only while their stage (or entry) is valid: no reset.
  always_ff @(posedge clk_i) begin
    if (req_fire) begin
      s1_u_q        <= req_u;
      s1_v_q        <= req_v;
      s1_shade_q    <= req_shade_i;
      s1_level0_q   <= lod_level0;
      s1_level1_q   <= lod_level1;
      s1_wl_q       <= lod_weight;
      s1_two_q      <= lod_two;
    end
    if (s2_load) begin
      s2_t0_q       <= axis_t0;
      s2_w_q        <= axis_w;
      s2_shade_q    <= s1_shade_q;
      s2_level0_q   <= s1_level0_q;
      s2_level1_q   <= s1_level1_q;
      s2_wl_q       <= s1_wl_q;
      s2_two_q      <= s1_two_q;
    end
    if (s3_load) begin
      for (int n = 0; n < 8; n++) s3_sub_q[n*2 +: 2] <= bord_coord[n*CoordW +: 2];
      s3_stored_q   <= bord_stored;
      s3_outside_q  <= bord_outside;
      s3_w_q        <= s2_w_q;
      s3_shade_q    <= s2_shade_q;
      s3_level0_q   <= s2_level0_q;
      s3_level1_q   <= s2_level1_q;
      s3_wl_q       <= s2_wl_q;
      s3_two_q      <= s2_two_q;
    end
    if (s4_load) begin
      s4_read_q <= tap_read;
      s4_bank_q <= tap_bank;
      s4_addr_q <= tap_addr;
      // wx and wy of each level from the axis weights (index 2 j + a).
      s4_info_q <= {s3_shade_q, s3_wl_q, s3_w_q[3*W +: W], s3_w_q[1*W +: W],
                    s3_w_q[2*W +: W], s3_w_q[0*W +: W], tap_info};
    end
  end

  // ---- Assertions ---------------------------------------------------------------------------
  // They run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions and
  // defines SYNTHESIS.
`ifndef SYNTHESIS
  // Taps in one bank need one cell (the layout guarantees it; golden throws otherwise).
  logic bank_conflict;
  always_comb begin
    bank_conflict = 1'b0;
    for (int s = 0; s < Taps; s++) begin
      for (int t = 0; t < Taps; t++) begin
        if (tap_read[s] && tap_read[t] && tap_bank[s*3 +: 3] == tap_bank[t*3 +: 3] &&
            tap_addr[s*AddrW +: AddrW] != tap_addr[t*AddrW +: AddrW]) begin
          bank_conflict = 1'b1;
        end
      end
    end
  end
  property p_one_cell_per_bank;
    @(posedge clk_i) disable iff (!rst_ni) s3_valid_q |-> !bank_conflict;
  endproperty
  a_one_cell_per_bank: assert property (p_one_cell_per_bank);

  // The configuration is held: a change while samples are in flight is a misuse.
  property p_cfg_stable;
    @(posedge clk_i) disable iff (!rst_ni)
      !clut_ready_o |=> ($stable(cfg_log2_w_i) && $stable(cfg_log2_h_i) && $stable(cfg_kind_i) &&
                         $stable(cfg_filter_i) && $stable(cfg_border_u_i) &&
                         $stable(cfg_border_v_i));
  endproperty
  a_cfg_stable: assert property (p_cfg_stable);
`endif

endmodule
