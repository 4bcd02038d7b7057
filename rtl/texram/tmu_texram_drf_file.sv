/// The TEXRAM chip's seven description register files (000 §14; docs/texram_chip.md), bit-exact
/// with golden texram::chip::apply (golden/texram/chip/drf.cpp, the specification of the write
/// decode): a write {drf, field, value} loads one field of DRF drf (1..7); DRF 0 drops the write,
/// fields above 10 change nothing, and the cube faces (fields 5..10) exist in DRF 7 only. Bits
/// above a field's width are ignored.
///
///   field 0 base     value[20:0]
///   field 1 shape    log2_w 3:0, log2_h 7:4, kind 10:8, single_channel 12:11, filter 14:13,
///                    border_u 16:15, border_v 18:17, addressing 19, cube 20
///   field 2 border colour, field 3 constant (RGBA8888)
///   field 4 control  op 2:0, link 5:3, takes_coords 6, combine 8:7, footprint 9,
///                    log2_max_probes 12:10, q_rule 13, detail 14, detail_combine 15
///   fields 5..10     DRF 7's face bases +X, -X, +Y, -Y, +Z, -Z
///
/// Two read ports, combinational, because a step reads one DRF's map while the sequencer
/// follows another (a detail map's offsets and detail DRFs are read under their texture's
/// step):
///   map port (rd_*)      what the trilinear unit reads: DRF rd_drf_i's shape, colours,
///                        combine and the map's base: the base, or with the cube bit the face
///                        rd_face_i's base (a face taken modulo 6; DRFs 1..6 hold no faces, so
///                        theirs is 0, as golden's zero-initialised face_base) unless
///                        rd_own_base_i asks for the DRF's own base (golden reads an offsets or
///                        detail DRF's map at its base, cube bit or not)
///   control port (ctl_*) what the sequencer follows: DRF ctl_drf_i's control word, border
///                        modes (the footprint marcher wraps or saturates by them), combine and
///                        constant (eq. 5 after a detail combine; an environment's k_s)
/// and every DRF's link (links_o, DRF n's at [3 (n - 1) +: 3]): the chain past a detail map.
/// The registers reset to golden's DrfFile{}: every field 0 but the filter, trilinear
/// (SamplerConfig's default), and log2_max_probes 3 (footprint::Config's), so a pixel before
/// any write is golden's too.
module tmu_texram_drf_file (
  input  logic                   clk_i,
  input  logic                   rst_ni,

  /// Write: DRF wr_drf_i's field wr_field_i <= wr_value_i.
  input  logic                   wr_en_i,
  input  tmu_pkg::drf_index_t    wr_drf_i,
  input  tmu_pkg::drf_field_t    wr_field_i,
  input  tmu_pkg::drf_value_t    wr_value_i,

  /// Map port: DRF rd_drf_i (1..7; 0 reads DRF 1's registers, which the sequencer never uses),
  /// the cube face rd_face_i, or the DRF's own base (rd_own_base_i).
  input  tmu_pkg::drf_index_t    rd_drf_i,
  input  tmu_pkg::cube_face_t    rd_face_i,
  input  logic                   rd_own_base_i,
  output tmu_pkg::bank_addr_t    rd_base_o,
  output tmu_pkg::mip_log2_t     rd_log2_w_o,
  output tmu_pkg::mip_log2_t     rd_log2_h_o,
  output tmu_pkg::tex_kind_t     rd_kind_o,
  output tmu_pkg::byte_plane_t   rd_single_channel_o,
  output tmu_pkg::tex_filter_t   rd_filter_o,
  output tmu_pkg::tex_border_t   rd_border_u_o,
  output tmu_pkg::tex_border_t   rd_border_v_o,
  output tmu_pkg::tex_addressing_t rd_addressing_o,
  output tmu_pkg::rgba8888_t     rd_border_rgba_o,
  output tmu_pkg::rgba8888_t     rd_constant_rgba_o,
  output tmu_pkg::tex_combine_t  rd_combine_o,

  /// Control port: DRF ctl_drf_i (0 reads DRF 1's, as the map port).
  input  tmu_pkg::drf_index_t    ctl_drf_i,
  output tmu_pkg::drf_op_t       ctl_op_o,
  output tmu_pkg::drf_index_t    ctl_link_o,
  output logic                   ctl_takes_coords_o,
  output logic                   ctl_footprint_o,
  output tmu_pkg::probe_log2_t   ctl_log2_max_probes_o,
  output tmu_pkg::q_rule_t       ctl_q_rule_o,
  output logic                   ctl_detail_o,
  output tmu_pkg::tex_detail_combine_t ctl_detail_combine_o,
  output tmu_pkg::tex_border_t   ctl_border_u_o,
  output tmu_pkg::tex_border_t   ctl_border_v_o,
  output tmu_pkg::tex_combine_t  ctl_combine_o,
  output tmu_pkg::rgba8888_t     ctl_constant_rgba_o,

  /// Every DRF's link: DRF n's at [3 (n - 1) +: 3].
  output logic [tmu_pkg::Drfs*tmu_pkg::DrfIndexW-1:0] links_o
);

  localparam int unsigned Drfs     = tmu_pkg::Drfs;  // 7
  localparam int unsigned Faces    = 6;
  localparam int unsigned BaseW    = tmu_pkg::BankAddrW;
  localparam int unsigned ShapeW   = 21;
  localparam int unsigned ControlW = 16;
  localparam int unsigned LinkW    = tmu_pkg::DrfIndexW;
  // pack_shape(Drf{}): filter trilinear (2 at bits 14:13), every other field 0.
  localparam logic [ShapeW-1:0] ShapeReset = ShapeW'(2) << 13;
  // pack_control(Drf{}): log2_max_probes 3 (bits 12:10), every other field 0.
  localparam logic [ControlW-1:0] ControlReset = ControlW'(3) << 10;

  localparam tmu_pkg::drf_field_t FieldBase     = 4'd0;
  localparam tmu_pkg::drf_field_t FieldShape    = 4'd1;
  localparam tmu_pkg::drf_field_t FieldBorder   = 4'd2;
  localparam tmu_pkg::drf_field_t FieldConstant = 4'd3;
  localparam tmu_pkg::drf_field_t FieldControl  = 4'd4;
  localparam tmu_pkg::drf_field_t FieldFace0    = 4'd5;

  logic [BaseW-1:0]    base_q     [Drfs];
  logic [ShapeW-1:0]   shape_q    [Drfs];
  logic [31:0]         border_q   [Drfs];
  logic [31:0]         constant_q [Drfs];
  logic [ControlW-1:0] control_q  [Drfs];
  logic [BaseW-1:0]    face_q     [Faces];

  // ---- Write decode (golden apply) -----------------------------------------------------------

  logic [3:0] face_w;  // the written face: field - 5
  assign face_w = wr_field_i - FieldFace0;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      for (int n = 0; n < Drfs; n++) begin
        base_q[n]     <= '0;
        shape_q[n]    <= ShapeReset;
        border_q[n]   <= '0;
        constant_q[n] <= '0;
        control_q[n]  <= ControlReset;
      end
      for (int f = 0; f < Faces; f++) face_q[f] <= '0;
    end else if (wr_en_i && wr_drf_i != '0) begin
      for (int n = 0; n < Drfs; n++) begin
        if (32'(wr_drf_i) == n + 1) begin
          unique case (wr_field_i)
            FieldBase:     base_q[n]     <= wr_value_i[BaseW-1:0];
            FieldShape:    shape_q[n]    <= wr_value_i[ShapeW-1:0];
            FieldBorder:   border_q[n]   <= wr_value_i;
            FieldConstant: constant_q[n] <= wr_value_i;
            FieldControl:  control_q[n]  <= wr_value_i[ControlW-1:0];
            default: ;
          endcase
        end
      end
      for (int f = 0; f < Faces; f++) begin
        if (32'(wr_drf_i) == Drfs && wr_field_i >= FieldFace0 && 32'(face_w) == f) begin
          face_q[f] <= wr_value_i[BaseW-1:0];
        end
      end
    end
  end

  // ---- Read ----------------------------------------------------------------------------------

  // DRF n's registers are at slot n - 1 (DRF 0 reads slot 0).
  function automatic logic [2:0] slot_of(tmu_pkg::drf_index_t n);
    slot_of = n == '0 ? 3'd0 : n - 3'd1;
  endfunction

  logic [2:0]          slot, ctl_slot;
  logic [ShapeW-1:0]   shape, ctl_shape;
  logic [ControlW-1:0] control;
  assign slot      = slot_of(rd_drf_i);
  assign ctl_slot  = slot_of(ctl_drf_i);
  assign shape     = shape_q[slot];
  assign ctl_shape = shape_q[ctl_slot];
  assign control   = control_q[ctl_slot];

  assign rd_log2_w_o         = shape[3:0];
  assign rd_log2_h_o         = shape[7:4];
  assign rd_kind_o           = shape[10:8];
  assign rd_single_channel_o = shape[12:11];
  assign rd_filter_o         = shape[14:13];
  assign rd_border_u_o       = shape[16:15];
  assign rd_border_v_o       = shape[18:17];
  assign rd_addressing_o     = shape[19];
  assign rd_border_rgba_o    = border_q[slot];
  assign rd_constant_rgba_o  = constant_q[slot];
  assign rd_combine_o        = control_q[slot][8:7];

  assign ctl_op_o              = control[2:0];
  assign ctl_link_o            = control[5:3];
  assign ctl_takes_coords_o    = control[6];
  assign ctl_combine_o         = control[8:7];
  assign ctl_footprint_o       = control[9];
  assign ctl_log2_max_probes_o = control[12:10];
  assign ctl_q_rule_o          = control[13];
  assign ctl_detail_o          = control[14];
  assign ctl_detail_combine_o  = control[15];
  assign ctl_border_u_o        = ctl_shape[16:15];
  assign ctl_border_v_o        = ctl_shape[18:17];
  assign ctl_constant_rgba_o   = constant_q[ctl_slot];

  for (genvar n = 0; n < Drfs; n++) begin : gen_links
    assign links_o[n*LinkW +: LinkW] = control_q[n][5:3];
  end

  // The face modulo 6 (CubeFace is 3 bits: 6 and 7 are faces 0 and 1).
  logic [2:0] face;
  assign face = rd_face_i >= 3'd6 ? rd_face_i - 3'd6 : rd_face_i;

  always_comb begin
    if (!shape[20] || rd_own_base_i) rd_base_o = base_q[slot];
    else if (32'(rd_drf_i) == Drfs) rd_base_o = face_q[face];
    else rd_base_o = '0;
  end

  // The control port's shape bits other than the borders are the map port's business.
  logic unused_ctl_shape;
  assign unused_ctl_shape = ^{ctl_shape[20:19], ctl_shape[14:0]};

endmodule
