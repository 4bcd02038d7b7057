/// One axis of the tau unit's lookup (golden tau::axis_weights, steps 1-2's first half): a
/// parameter coordinate clamped into the grid, its cell_idx and its 12-bit weight fraction, and
/// the fraction's square. Combinational.
///
///   c = clamp(coord, 0, cells 2^16); cell_idx = min(c >> 16, cells - 1)
///   x = (c - cell_idx 2^16) >> 4 (truncated: below the exact fraction by less than 2^-12 cell_idx;
///   x = 2^12 only at c = cells), x2 = (x x + 2^11) >> 12
///
/// Example: cells 3, coord 0x018000 (1.5 cells): cell_idx 1, x = 0x800, x2 = 0x400.
/// coord 0x030000 (3.0 = cells): cell_idx 2, x = 0x1000, x2 = 0x1000.
module tmu_tau_axis (
  /// The coordinate, PcCoord SQ8.16 cells.
  input  tmu_pkg::pc_coord_t coord_i,
  /// The grid's cells along this axis, already 1..16.
  input  logic [4:0]         cells_i,
  output logic [3:0]         cell_o,
  /// x and x2 in units of 2^-12 cell_idx, 0 .. 2^12.
  output logic [12:0]        x_o,
  output logic [12:0]        x2_o
);

  localparam int unsigned CW = tmu_pkg::PcCoordW;  // 24
  localparam int unsigned Frac = tmu_pkg::PcCoordFrac;  // 16

  if (Frac != 16) begin : gen_check
    $error("tmu_tau_axis: built for 16 fraction bits of a parameter coordinate");
  end

  logic [20:0] top, clamped;  // 0 .. 16 2^16
  logic [4:0]  whole;
  logic [3:0]  cell_idx;
  logic [25:0] square;

  assign top = {cells_i, 16'b0};
  always_comb begin
    if (coord_i[CW-1]) begin
      clamped = '0;
    end else if ({1'b0, coord_i[CW-2:0]} > (CW)'(top)) begin
      clamped = top;
    end else begin
      clamped = 21'(coord_i[CW-2:0]);
    end
  end
  assign whole  = clamped[20:16];
  assign cell_idx   = whole >= cells_i ? 4'(cells_i - 5'd1) : whole[3:0];
  // c - cell_idx 2^16 is at most 2^16 (c = cells): 17 bits, of which the top 13 are x.
  assign x_o    = 13'((clamped - {1'b0, cell_idx, 16'b0}) >> 4);
  assign square = 26'(x_o) * 26'(x_o);
  assign x2_o   = 13'((square + 26'd2048) >> 12);
  assign cell_o = cell_idx;

endmodule
