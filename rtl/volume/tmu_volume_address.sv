/// The bank address of voxel (x, y, z) in the volume layout (golden VolumeGeometry::cell,
/// golden/volume/layout.hpp): bricks of 16 x 8 x 16 voxels, 8 x 4 x 16 = 512 cells of each
/// bank, one DRAM page; the bricks x fastest, then y, then z:
///   address = 512 brick + 32 (z & 15) + 8 ((y >> 1) & 3) + ((x >> 1) & 7)
///   brick   = (x >> 4) + BX ((y >> 3) + BY (z >> 4)),  BX = ceil(X / 16), BY = ceil(Y / 8)
/// (the bank, (x & 1) + 2 (y & 1), is the caller's). Combinational; the caller reads only
/// voxels inside the volume, whose bricks fit the 21-bit address (golden rejects larger ones).
///
/// Example: a 40 x 20 x 20 volume (BX = 3, BY = 3), voxel (21, 9, 17): brick 1 + 3 (1 + 3 1)
/// = 13, address 13 512 + 32 1 + 8 0 + 2 = 6690.
module tmu_volume_address (
  input  logic [9:0]          x_i,
  input  logic [9:0]          y_i,
  input  logic [9:0]          z_i,
  /// BX and BY: bricks along x and y.
  input  logic [6:0]          bricks_x_i,
  input  logic [7:0]          bricks_y_i,
  output tmu_pkg::bank_addr_t addr_o
);

  localparam int unsigned AW = tmu_pkg::BankAddrW;  // 21: 12 bits of brick, 9 of cell

  if (AW != 21 || tmu_pkg::VolumeBrickCells != 512) begin : gen_check
    $error("tmu_volume_address: built for 21-bit bank addresses and bricks of 512 cells");
  end

  logic [13:0] slab;   // BY (z >> 4)
  logic [14:0] row;    // (y >> 3) + BY (z >> 4)
  logic [21:0] brick;  // (x >> 4) + BX row
  assign slab   = bricks_y_i * z_i[9:4];
  assign row    = 15'(y_i[9:3]) + 15'(slab);
  assign brick  = 22'(x_i[9:4]) + bricks_x_i * row;
  assign addr_o = {brick[11:0], z_i[3:0], y_i[2:1], x_i[3:1]};

  logic unused_bits;
  assign unused_bits = ^{brick[21:12], x_i[0], y_i[0]};

endmodule
