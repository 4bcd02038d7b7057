/// The colour of one tap from the bytes its bank delivered (000 §6: luminance, index, true
/// colour, single component; §3: CCC), exactly as texram::tap_colour (golden/texram/
/// trilinear.cpp), split around the CLUT: the unit looks up clut_index_o in its eight-port
/// CLUT and takes that entry when use_clut_o is set, else colour_o. Combinational.
///
///   outside        the border colour
///   luminance      (b0, b0, b0, 255)
///   single         b0 in channel single_channel_i (0 R .. 3 A), the other colour channels 0,
///                  alpha 255 (channel A: (0, 0, 0, b0))
///   true colour    (b0, b1, b2, b3)
///   index          CLUT[b0]
///   CCC            CLUT[b or a], the block word b0 b1 b2 b3 (bits 31:24 first) decoded at
///                  texel (tx, ty) of its 4 x 4 block: decision bit 4 ty + tx selects b1
///                  (colour b) over b0 (colour a) (Fig. 5)
///
/// Example: CCC, bytes 0x12 0x34 0x80 0x00 (decision bits 0x8000), texel (3, 3): bit 15 is
/// set, CLUT index 0x34.
module tmu_trilinear_texel (
  /// The tap's bytes b0 (31:24) .. b3 (7:0): plane p of its bank in byte 3 - p.
  input  tmu_pkg::rgba8888_t   bytes_i,
  input  logic                 outside_i,
  /// The tap's texel within its CCC block.
  input  logic [1:0]           tx_i,
  input  logic [1:0]           ty_i,
  /// The texel configuration, decoded (none set: luminance).
  input  logic                 index_i,
  input  logic                 true_colour_i,
  input  logic                 single_i,
  input  logic                 ccc_i,
  input  tmu_pkg::byte_plane_t single_channel_i,
  input  tmu_pkg::rgba8888_t   border_rgba_i,
  /// The colour, unless use_clut_o: then CLUT entry clut_index_o.
  output tmu_pkg::rgba8888_t   colour_o,
  output logic                 use_clut_o,
  output tmu_pkg::clut_index_t clut_index_o
);

  localparam int unsigned ChW = tmu_pkg::ChannelW;  // 8

  tmu_pkg::channel_t b0, b1;
  logic [15:0]       decision;

  assign b0       = bytes_i[31:24];
  assign b1       = bytes_i[23:16];
  assign decision = bytes_i[15:0];

  assign use_clut_o   = !outside_i && (index_i || ccc_i);
  assign clut_index_o = ccc_i && decision[{ty_i, tx_i}] ? b1 : b0;

  always_comb begin
    if (outside_i) begin
      colour_o = border_rgba_i;
    end else if (true_colour_i) begin
      colour_o = bytes_i;
    end else if (single_i) begin
      if (single_channel_i == 2'd3) begin
        colour_o = {(3 * ChW)'(0), b0};
      end else begin
        colour_o = ({b0, (3 * ChW)'(0)} >> (ChW * 32'(single_channel_i))) | 32'h0000_00FF;
      end
    end else begin
      colour_o = {b0, b0, b0, 8'hFF};  // luminance (index and CCC take the CLUT)
    end
  end

endmodule
