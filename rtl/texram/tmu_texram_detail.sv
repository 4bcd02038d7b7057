/// The TEXRAM chip's detail unit (000 §9; docs/detail.md, docs/texram_chip.md), bit-exact with
/// golden texram::chip::sample_with_detail (golden/texram/chip/chip_step.cpp) on its detail
/// path: a sample of a texture (or reflectance) DRF t with the detail flag at lambda < 0, whose
/// link is an offsets DRF o that links to a detail DRF d. It makes the sample's map reads one
/// at a time through the chip's trilinear unit (its read port: which DRF's map, the request)
/// and combines them:
///   OU  o's map at (u, v, lambda 0, shade 0), o's own base: the u offset (the colour's red);
///       the region is missing when that read's first tap of level 0 is outside o's map
///       (tmu_texram_tap0_outside on the map port's configuration, o's while the read is issued)
///   OV  o's map again, at the v-offset map: o's base + its one-plane cells rounded up to a page
///   T0  (no region) t's map at (u, v, 0, shade): the sample
///   D   d's map at u_d = (ou << 8) + (frac(u) << 4), v_d likewise, lambda_d, shade 0, d's own
///       base: the detail colour
///   T1  (modulate, or -1 < lambda < 0) t's map at (u, v, 0, 0) with eq. 5 "one": the texel
///   then tmu_texram_detail_combine (replace or modulate by wt, then t's eq. 5 with the shade).
/// lambda_d and wt (golden texram::detail_levels at the chip's widths, L = W = 8): lambda <= -1:
/// lambda_d = lambda + 4, wt = 0; -1 < lambda < 0: lambda_d = 3, wt = lambda + 1 (8 bits).
///
/// The chip maps rd_map_o to a DRF number for its DRF file's map port and keeps that port on
/// the read until its result is taken: one read in flight, so the trilinear unit's
/// configuration changes only while it is empty.
///
/// Timing: a probe is taken in the idle state; each read is issued the next cycle (1 cycle when
/// the unit is ready) and its result taken when it comes (the unit's 12 cycles at page hits);
/// the colour is in the output register the cycle after the last result and leaves when taken.
/// With page hits: 13 cycles a read, 2 more a probe: 41 cycles for three reads (replace at
/// lambda <= -1), 54 for four.
///
/// Example: u = 2.75 texels (raw 0x2C0), lambda = -2 (raw -0x200), replace: lambda_d = 2.0,
/// wt = 0; o's map gives ou = 0x30 at texel 2: u_d = 0x3000 + 0xC00 = 0x3C00 (60 texels of the
/// detail map's level 0); the texel read is skipped: three reads.
module tmu_texram_detail (
  input  logic                         clk_i,
  input  logic                         rst_ni,

  /// t's detail rule (0 replace, 1 modulate) and eq. 5 (selection, k_T): held for the probe.
  input  tmu_pkg::tex_detail_combine_t modulate_i,
  input  tmu_pkg::tex_combine_t        combine_i,
  input  tmu_pkg::rgba8888_t           constant_rgba_i,

  /// A probe on the detail path (the step's request or a footprint probe), lambda < 0.
  input  logic                         in_valid_i,
  output logic                         in_ready_o,
  input  tmu_pkg::tex_coord_t          in_u_i,
  input  tmu_pkg::tex_coord_t          in_v_i,
  input  tmu_pkg::lod_t                in_lambda_i,
  input  tmu_pkg::rgba8888_t           in_shade_i,

  /// A read: the map (0 t, 1 o, 2 d), cells to add to the map port's base (the v-offset
  /// map's distance), eq. 5 forced to "one", and the request.
  output logic                         rd_valid_o,
  input  logic                         rd_ready_i,
  output logic [1:0]                   rd_map_o,
  output tmu_pkg::bank_addr_t          rd_base_add_o,
  output logic                         rd_one_o,
  output tmu_pkg::tex_coord_t          rd_u_o,
  output tmu_pkg::tex_coord_t          rd_v_o,
  output tmu_pkg::lod_t                rd_lambda_o,
  output tmu_pkg::rgba8888_t           rd_shade_o,

  /// The map port's configuration (the DRF rd_map_o names).
  input  tmu_pkg::mip_log2_t           map_log2_w_i,
  input  tmu_pkg::mip_log2_t           map_log2_h_i,
  input  tmu_pkg::tex_filter_t         map_filter_i,
  input  tmu_pkg::tex_border_t         map_border_u_i,
  input  tmu_pkg::tex_border_t         map_border_v_i,
  input  tmu_pkg::tex_addressing_t     map_addressing_i,
  input  logic                         map_block_grid_i,

  /// The read's colour, in order, one per read.
  input  logic                         res_valid_i,
  output logic                         res_ready_o,
  input  tmu_pkg::rgba8888_t           res_rgba_i,

  /// The probe's colour.
  output logic                         out_valid_o,
  input  logic                         out_ready_i,
  output tmu_pkg::rgba8888_t           out_rgba_o,

  /// A probe is in the unit (its reads own the trilinear unit).
  output logic                         busy_o
);

  localparam int unsigned CW     = tmu_pkg::ChannelW;     // 8
  localparam int unsigned Frac   = tmu_pkg::TexCoordFrac;  // 8
  localparam int unsigned CoordW = tmu_pkg::TexCoordW;     // 24
  localparam int unsigned LodW   = tmu_pkg::LodW;          // 14
  localparam int unsigned AddrW  = tmu_pkg::BankAddrW;     // 21
  localparam int unsigned Log2W  = tmu_pkg::MipLog2W;      // 4
  localparam int unsigned PageW  = tmu_pkg::PageLog2;      // 9
  localparam int unsigned W      = 8;                      // the chip's weight bits
  localparam int unsigned RegionLog2 = tmu_pkg::DetailLevels;  // a region is 2^4 texels a side
  localparam logic signed [LodW-1:0] Level = LodW'(1) << tmu_pkg::LodFrac;  // one level

  if (tmu_pkg::LodFrac != W || Frac != 8 || (1 << RegionLog2) != tmu_pkg::DetailRegionSide)
  begin : gen_check
    $error("tmu_texram_detail: built for 8 fraction bits of lambda and of coordinates");
  end

  localparam logic [1:0] MapT = 2'd0;
  localparam logic [1:0] MapO = 2'd1;
  localparam logic [1:0] MapD = 2'd2;

  typedef enum logic [1:0] {
    EIdle,   // takes a probe
    EIssue,  // the read's request
    EWait,   // its result
    EOut     // the colour waits to be taken
  } state_e;

  typedef enum logic [2:0] {
    ReadOu,  // u offset
    ReadOv,  // v offset
    ReadT0,  // no region: the texture at level 0 is the sample
    ReadD,   // the detail map
    ReadT1   // the texel for the combine
  } read_e;

  state_e              state_q;
  read_e               read_q;
  tmu_pkg::tex_coord_t u_q, v_q;
  tmu_pkg::rgba8888_t  shade_q, detail_q, out_rgba_q;
  tmu_pkg::lod_t       lambda_d_q;
  logic [W-1:0]        wt_q;
  tmu_pkg::detail_offset_t ou_q, ov_q;
  logic                outside_q;

  // ---- lambda_d and wt (golden detail_levels, L = W = 8) ---------------------------------------

  tmu_pkg::lod_t lambda_d;
  logic [W-1:0]  wt;
  always_comb begin
    if (in_lambda_i <= -Level) begin
      lambda_d = in_lambda_i + (Level <<< 2);  // lambda + 4
      wt       = '0;
    end else begin
      lambda_d = Level * 3;                    // level -1 alone
      wt       = W'(in_lambda_i + Level);      // the fraction lambda + 1, 1 .. 255
    end
  end

  // ---- The reads -------------------------------------------------------------------------------

  // The detail map's coordinate: the region's first texel plus 16 times the fraction, exact.
  function automatic tmu_pkg::tex_coord_t detail_coord(tmu_pkg::detail_offset_t offset,
                                                       logic [Frac-1:0] fraction);
    detail_coord = (CoordW'(offset) << Frac) + (CoordW'(fraction) << RegionLog2);
  endfunction

  // The v-offset map after the u map: its one-plane cells (golden Geometry::bank_cells: the
  // fuller parity's positions, level l taking 2^(max(a-l-1,0) + max(b-l-1,0))) rounded up to a
  // page (offsets_v_base).
  function automatic logic [Log2W-1:0] half_log2(tmu_pkg::mip_log2_t side, int level);
    half_log2 = 32'(side) > level + 1 ? Log2W'(32'(side) - level - 1) : '0;
  endfunction
  // log2 of level l's positions in its banks.
  function automatic logic [Log2W:0] level_cells_log2(tmu_pkg::mip_log2_t w,
                                                      tmu_pkg::mip_log2_t h, int level);
    level_cells_log2 = (Log2W + 1)'(half_log2(w, level)) + (Log2W + 1)'(half_log2(h, level));
  endfunction

  tmu_pkg::mip_log2_t  top;
  logic [AddrW-1:0]    used_even, used_odd, cells;
  tmu_pkg::bank_addr_t v_distance;
  assign top = map_log2_w_i > map_log2_h_i ? map_log2_w_i : map_log2_h_i;
  always_comb begin
    used_even = '0;
    used_odd  = '0;
    for (int l = 0; l <= tmu_pkg::MaxMipLog2; l++) begin
      if (l <= 32'(top)) begin
        if (l % 2 == 0) begin
          used_even = used_even + (AddrW'(1) << level_cells_log2(map_log2_w_i, map_log2_h_i, l));
        end else begin
          used_odd = used_odd + (AddrW'(1) << level_cells_log2(map_log2_w_i, map_log2_h_i, l));
        end
      end
    end
  end
  assign cells      = used_even > used_odd ? used_even : used_odd;
  assign v_distance = (cells + AddrW'((1 << PageW) - 1)) & ~AddrW'((1 << PageW) - 1);

  logic outside;
  tmu_texram_tap0_outside u_outside (
    .u_i          (u_q),
    .v_i          (v_q),
    .log2_w_i     (map_log2_w_i),
    .log2_h_i     (map_log2_h_i),
    .filter_i     (map_filter_i),
    .border_u_i   (map_border_u_i),
    .border_v_i   (map_border_v_i),
    .addressing_i (map_addressing_i),
    .block_grid_i (map_block_grid_i),
    .outside_o    (outside)
  );

  always_comb begin
    rd_map_o      = MapT;
    rd_base_add_o = '0;
    rd_one_o      = 1'b0;
    rd_u_o        = u_q;
    rd_v_o        = v_q;
    rd_lambda_o   = '0;
    rd_shade_o    = '0;
    unique case (read_q)
      ReadOu: rd_map_o = MapO;
      ReadOv: begin
        rd_map_o      = MapO;
        rd_base_add_o = v_distance;
      end
      ReadT0: rd_shade_o = shade_q;
      ReadD: begin
        rd_map_o    = MapD;
        rd_u_o      = detail_coord(ou_q, u_q[Frac-1:0]);
        rd_v_o      = detail_coord(ov_q, v_q[Frac-1:0]);
        rd_lambda_o = lambda_d_q;
      end
      ReadT1: rd_one_o = 1'b1;
      default: ;
    endcase
  end

  // ---- The combine -----------------------------------------------------------------------------

  tmu_pkg::rgba8888_t combined;
  tmu_texram_detail_combine #(.WeightBits(W)) u_combine (
    .detail_i        (read_q == ReadD ? res_rgba_i : detail_q),
    .texel_i         (read_q == ReadT1 ? res_rgba_i : '0),
    .wt_i            (wt_q),
    .modulate_i      (modulate_i),
    .combine_i       (combine_i),
    .constant_rgba_i (constant_rgba_i),
    .shade_i         (shade_q),
    .rgba_o          (combined)
  );

  // ---- Control ---------------------------------------------------------------------------------

  logic in_fire, rd_fire, res_fire, need_texel;
  assign in_ready_o  = state_q == EIdle;
  assign in_fire     = in_valid_i && in_ready_o;
  assign rd_valid_o  = state_q == EIssue;
  assign rd_fire     = rd_valid_o && rd_ready_i;
  assign res_ready_o = state_q == EWait;
  assign res_fire    = res_valid_i && res_ready_o;
  assign out_valid_o = state_q == EOut;
  assign out_rgba_o  = out_rgba_q;
  assign busy_o      = state_q != EIdle;
  assign need_texel  = modulate_i || wt_q != '0;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= EIdle;
      read_q  <= ReadOu;
    end else begin
      unique case (state_q)
        EIdle: if (in_fire) begin
          read_q  <= ReadOu;
          state_q <= EIssue;
        end
        EIssue: if (rd_fire) state_q <= EWait;
        EWait: if (res_fire) begin
          state_q <= EIssue;
          unique case (read_q)
            ReadOu: read_q <= ReadOv;
            ReadOv: read_q <= outside_q ? ReadT0 : ReadD;
            ReadD: begin
              if (need_texel) read_q <= ReadT1;
              else state_q <= EOut;
            end
            default: state_q <= EOut;  // T0, T1: the last read
          endcase
        end
        EOut: if (out_ready_i) state_q <= EIdle;
        default: state_q <= EIdle;
      endcase
    end
  end

  // Data registers: each is written before the state that reads it (a probe's first).
  always_ff @(posedge clk_i) begin
    if (in_fire) begin
      u_q        <= in_u_i;
      v_q        <= in_v_i;
      shade_q    <= in_shade_i;
      lambda_d_q <= lambda_d;
      wt_q       <= wt;
    end
    if (rd_fire && read_q == ReadOu) outside_q <= outside;
    if (res_fire) begin
      unique case (read_q)
        ReadOu: ou_q <= res_rgba_i[4*CW-1 -: CW];
        ReadOv: ov_q <= res_rgba_i[4*CW-1 -: CW];
        ReadT0: out_rgba_q <= res_rgba_i;
        ReadD: begin
          detail_q   <= res_rgba_i;
          out_rgba_q <= combined;
        end
        ReadT1: out_rgba_q <= combined;
        default: ;
      endcase
    end
  end

`ifndef SYNTHESIS
  // Only probes on the detail path come here.
  property p_negative_lambda;
    @(posedge clk_i) disable iff (!rst_ni) in_fire |-> in_lambda_i < 0;
  endproperty
  a_negative_lambda: assert property (p_negative_lambda);
`endif

endmodule
