/// Bank and cell of a clip-map texel (golden clipmap::ClipGeometry::cell and the stored
/// position of plan_clip_sample, golden/clipmap/clip_geometry.hpp and clipmap.cpp, the
/// specification). Level l is stored as a square of side s = 2^min(V - l, t) (at least 2: a
/// 1 x 1 level is stored replicated); the virtual texel (x, y) of the level sits at (x mod s,
/// y mod s), toroidal in a tile; a 1 x 1 level's replica is the parity of the tap's unresolved
/// coordinate (replica_x_i, replica_y_i), so that neighbouring taps use different banks. Then
/// 000 Fig. 2's layout:
///   bank     = 4 (l & 1) + 2 (sy & 1) + (sx & 1)
///   position = offset(l) + (sy >> 1) * (stored side / 2) + (sx >> 1)
///   address  = 4 position + plane (four planes) or position
/// offset(l), the positions of the levels of l's parity below l, comes from tmu_clip_offsets
/// (one table a clip-map, shared by every tap). Combinational.
///
/// Example: V = 8, t = 5, level 2 (a 32 x 32 tile, offset 256), virtual (70, 33): stored
/// (6, 1), bank 0 + 2 + 0 = 2, position 256 + 0 * 16 + 3 = 259.
module tmu_clip_address (
  input  tmu_pkg::clip_log2_t   log2_virtual_i,
  input  tmu_pkg::mip_log2_t    log2_tile_i,
  input  logic                  four_planes_i,
  input  tmu_pkg::bank_addr_t   offset_i,      // offset(level_i)
  input  tmu_pkg::mip_level_t   level_i,
  input  tmu_pkg::clip_coord_t  x_i,
  input  tmu_pkg::clip_coord_t  y_i,
  input  logic                  replica_x_i,
  input  logic                  replica_y_i,
  input  tmu_pkg::byte_plane_t  plane_i,
  output tmu_pkg::bank_t        bank_o,
  output tmu_pkg::bank_addr_t   addr_o
);

  localparam int unsigned AddrW  = tmu_pkg::BankAddrW;
  localparam int unsigned Log2W  = tmu_pkg::MipLog2W;
  localparam int unsigned CoordW = tmu_pkg::ClipCoordW;

  logic [Log2W-1:0]  side_log2;  // min(V - l, t)
  logic [CoordW-1:0] mask;       // s - 1
  logic [CoordW-1:0] sx, sy;     // the stored position
  logic [Log2W-1:0]  row_log2;   // log2 of the positions a row: max(side_log2, 1) - 1
  logic [AddrW-1:0]  position;

  always_comb begin
    side_log2 = Log2W'(log2_virtual_i) > Log2W'(level_i) ? Log2W'(log2_virtual_i) - Log2W'(level_i)
                                                         : '0;
    if (side_log2 > log2_tile_i) side_log2 = log2_tile_i;
  end
  assign mask     = CoordW'((32'd1 << side_log2) - 32'd1);
  assign sx       = side_log2 == '0 ? CoordW'(replica_x_i) : x_i & mask;
  assign sy       = side_log2 == '0 ? CoordW'(replica_y_i) : y_i & mask;
  assign row_log2 = side_log2 == '0 ? '0 : side_log2 - Log2W'(1);
  assign position = offset_i + (AddrW'(sy[CoordW-1:1]) << row_log2) + AddrW'(sx[CoordW-1:1]);
  assign addr_o   = (four_planes_i ? {position[AddrW-3:0], 2'b00} : position) + AddrW'(plane_i);
  assign bank_o   = {level_i[0], sy[0], sx[0]};

endmodule
