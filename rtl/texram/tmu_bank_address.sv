/// TEXRAM bank and cell address of a stored texel (000 §2, Fig. 2: "all address calculations
/// ... performed locally"), exactly as texram::Geometry::cell (golden/texram/layout.hpp):
///
///   bank     = 4 (level & 1) + 2 (y & 1) + (x & 1)
///   position = offset(level) + (y >> 1) * (stored width / 2) + (x >> 1)
///   address  = planes * position + plane                    (planes = 4 or 1)
///
/// where level l of a 2^a x 2^b texture is a grid of max(2^(a-l), 1) texels (block grid:
/// ceil of that / 4 CCC blocks) per row, stored at least 2 wide and 2 high, and offset(l) is
/// the number of positions the levels of l's parity below l take in their banks. Every stored
/// size is a power of two, so the row length is a shift and offset(l) a sum of powers of two:
/// no multiplier. Purely combinational; the trilinear unit uses it too.
///
/// x and y are stored coordinates (0 .. stored size - 1: a grid position or its replica).
/// Inputs outside the layout give an address outside it; nothing is checked here.
///
/// Example: 8 x 2 texture, one plane, level 1 (4 x 1 texels, stored 4 x 2), x = 3, y = 1:
/// bank = 4 + 2 + 1 = 7; level 1 is the first odd level, offset 0; position = 0 + 0 * 2 + 1
/// = 1; address 1. With four planes and plane 2: address 4 * 1 + 2 = 6.
module tmu_bank_address #(
  /// Largest texture side 2^MaxLog2 (sets the levels the offset sum covers).
  parameter int unsigned MaxLog2 = tmu_pkg::MaxMipLog2
) (
  /// Texture size: log2 of the level-0 width and height in texels.
  input  tmu_pkg::mip_log2_t   cfg_log2_w_i,
  input  tmu_pkg::mip_log2_t   cfg_log2_h_i,
  /// The texture has four byte planes (true colour, CCC), else one.
  input  logic                 cfg_four_planes_i,
  /// The grid is 4 x 4 CCC blocks (x, y are block coordinates), else texels.
  input  logic                 cfg_block_grid_i,
  /// The stored position and the byte plane.
  input  tmu_pkg::mip_level_t  in_level_i,
  input  tmu_pkg::mip_coord_t  in_x_i,
  input  tmu_pkg::mip_coord_t  in_y_i,
  input  tmu_pkg::byte_plane_t in_plane_i,
  /// Its bank and cell address within the bank.
  output tmu_pkg::bank_t       out_bank_o,
  output tmu_pkg::bank_addr_t  out_addr_o
);

  localparam int unsigned AddrW  = tmu_pkg::BankAddrW;
  localparam int unsigned LevelW = tmu_pkg::MipLevelW;
  localparam int unsigned Log2W  = tmu_pkg::MipLog2W;
  localparam int unsigned CoordW = tmu_pkg::MipCoordW;
  localparam int unsigned CellsW = Log2W + 1;  // log2 of a level's positions: up to 2 (MaxLog2 - 1)

  // Positions of the largest texture's level 0 (2^(2 MaxLog2 - 2)) times four planes must fit.
  if (MaxLog2 < 1 || MaxLog2 > tmu_pkg::MaxMipLog2 || 2 * MaxLog2 + 1 > AddrW) begin : gen_check
    $error("tmu_bank_address: MaxLog2 must be 1..MaxMipLog2");
  end

  // log2 of half the stored size of a level along one axis: max(side - level - 1, 0) for
  // texels, max(side - level - 3, 0) for blocks (the grid is a quarter of the texels, at
  // least one, and the stored size at least 2).
  function automatic logic [Log2W-1:0] half_log2(tmu_pkg::mip_log2_t side,
                                                 tmu_pkg::mip_level_t level, logic blocks);
    logic [LevelW+1:0] drop;
    drop = (LevelW + 2)'(level) + (blocks ? (LevelW + 2)'(3) : (LevelW + 2)'(1));
    if ((LevelW + 2)'(side) > drop) begin
      half_log2 = Log2W'((LevelW + 2)'(side) - drop);
    end else begin
      half_log2 = '0;
    end
  endfunction

  logic [AddrW-1:0]  offset;      // first position of in_level_i in its banks
  logic [CellsW-1:0] cells_log2;  // log2 of the positions of one level (loop variable)
  logic [AddrW-1:0]  position;
  logic [Log2W-1:0]  row_log2;    // log2 of the positions per row of in_level_i

  always_comb begin
    offset     = '0;
    cells_log2 = '0;
    for (int l = 0; l < MaxLog2; l++) begin
      cells_log2 = CellsW'(half_log2(cfg_log2_w_i, LevelW'(l), cfg_block_grid_i)) +
                   CellsW'(half_log2(cfg_log2_h_i, LevelW'(l), cfg_block_grid_i));
      if (LevelW'(l) < in_level_i && ((l % 2) == 1) == in_level_i[0]) begin
        offset = offset + (AddrW'(1) << cells_log2);
      end
    end
  end

  assign row_log2   = half_log2(cfg_log2_w_i, in_level_i, cfg_block_grid_i);
  assign position   = offset + (AddrW'(in_y_i[CoordW-1:1]) << row_log2) +
                      AddrW'(in_x_i[CoordW-1:1]);
  assign out_addr_o = (cfg_four_planes_i ? {position[AddrW-3:0], 2'b00} : position) +
                      AddrW'(in_plane_i);
  assign out_bank_o = {in_level_i[0], in_y_i[0], in_x_i[0]};

endmodule
