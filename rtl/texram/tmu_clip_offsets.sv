/// The first position of each level of a clip-map in its banks (golden
/// clipmap::ClipGeometry::level_offset, golden/clipmap/clip_geometry.hpp): offset(l) is the
/// sum, over the levels m < l of l's parity, of (stored side(m) / 2)^2 positions, the stored
/// side being 2^max(min(V - m, t), 1). Every term is a power of two: the table is shifts and
/// adders, from the configuration alone (quasi-static), shared by every tap. Combinational.
///
/// Example: V = 8, t = 5: even levels 0, 2, 4, 6, 8 at 0, 256, 512, 576, 580; odd levels 1, 3,
/// 5, 7 at 0, 256, 512, 528.
module tmu_clip_offsets #(
  parameter int unsigned Levels = 16
) (
  input  tmu_pkg::clip_log2_t log2_virtual_i,
  input  tmu_pkg::mip_log2_t  log2_tile_i,
  /// offset(l) at [l * BankAddrW +: BankAddrW].
  output logic [Levels*tmu_pkg::BankAddrW-1:0] offset_o
);

  localparam int unsigned AddrW = tmu_pkg::BankAddrW;
  localparam int unsigned Log2W = tmu_pkg::MipLog2W;

  // log2 of a level's positions: 2 (max(min(V - m, t), 1) - 1).
  function automatic logic [Log2W:0] cells_log2(tmu_pkg::mip_level_t m, tmu_pkg::clip_log2_t v,
                                                 tmu_pkg::mip_log2_t t);
    logic [Log2W-1:0] side;
    side = Log2W'(v) > Log2W'(m) ? Log2W'(v) - Log2W'(m) : '0;
    if (side > t) side = t;
    cells_log2 = side == '0 ? '0 : (Log2W + 1)'(side - Log2W'(1)) << 1;
  endfunction

  always_comb begin
    offset_o = '0;
    for (int l = 2; l < Levels; l++) begin
      offset_o[l*AddrW +: AddrW] = offset_o[(l-2)*AddrW +: AddrW] +
          (AddrW'(1) << cells_log2(tmu_pkg::MipLevelW'(l - 2), log2_virtual_i, log2_tile_i));
    end
  end

endmodule
