/// One axis of the low-cost unit's bilinear footprint (000 §4), the same arithmetic as the
/// golden ccc::footprint() and ccc::lookahead_blocks() (golden/ccc/ccc_cache_bilinear.cpp).
///
/// Footprint: i = floor(c - 0.5); t0 = clamp(i), t1 = clamp(i + 1) to 0..size-1 (clamp to
/// edge); frac = the 8 fraction bits of c - 0.5, the weight of t1.
/// Lookahead: t = clamp(floor(c)); blk = t / 4; the neighbour block is blk + 1 when bit 1 of
/// t is set (the point is in the far half of its block) and blk - 1 otherwise; it is inside
/// the texture when 0 <= nbr < ceil(size / 4).
///
/// Example (size 10): c = 3.25 (raw 0x000340) -> c - 0.5 = 2.75 -> t0 = 2, t1 = 3,
/// frac = 0xC0; t = 3 -> blk 0, bit 1 set -> nbr 1, inside (ceil(10/4) = 3).
/// c = -7.0 -> t0 = t1 = 0; t = 0 -> blk 0, nbr -1: outside.
module tmu_ccc_footprint_axis (
  /// Coordinate along the axis, SQ16.8 texels, texel centres at i + 0.5.
  input  tmu_pkg::tex_coord_t     coord_i,
  /// Texture size along the axis, 1..MaxTexSize.
  input  tmu_pkg::tex_size_t      size_i,
  /// Clamped footprint texels and the weight of t1_o.
  output logic [11:0]             t0_o,
  output logic [11:0]             t1_o,
  output tmu_pkg::filter_weight_t frac_o,
  /// Lookahead: block of the clamped floor(coord), its neighbour and whether that is inside.
  output logic [9:0]              blk_o,
  output logic [9:0]              nbr_o,
  output logic                    nbr_in_o
);

  // Texel coordinates 0..4095 (MaxTexSize), block coordinates 0..1023 (4 texels a block).
  localparam int unsigned TexelW = 12;
  localparam int unsigned BlockW = 10;
  localparam int unsigned CoordW = tmu_pkg::TexCoordW;
  localparam int unsigned Frac   = tmu_pkg::TexCoordFrac;
  localparam int unsigned SizeW  = tmu_pkg::TexSizeW;
  // floor(c - 0.5) + 1 spans -32768..32768: the integer part plus a sign and a carry bit.
  localparam int unsigned IntW   = CoordW - Frac + 2;
  localparam int unsigned SubW   = $clog2(tmu_pkg::CccBlockSide);

  // The fixed port widths follow from the format table; a change there must revisit them.
  if ((1 << TexelW) != tmu_pkg::MaxTexSize || BlockW != TexelW - SubW ||
      SizeW != TexelW + 1 || Frac != tmu_pkg::FilterWeightW) begin : gen_check_formats
    $error("tmu_ccc_footprint_axis: port widths do not match tmu_pkg");
  end

  logic [CoordW:0]    shifted;    // c - 0.5, one bit wider so it cannot wrap
  logic [IntW-1:0]    i0;         // floor(c - 0.5), two's complement
  logic [IntW-1:0]    i1;         // i0 + 1
  logic [IntW-1:0]    last;       // size - 1, zero-extended
  logic [IntW-1:0]    t_floor;    // floor(c), two's complement
  logic [TexelW-1:0]  t;          // clamp(floor(c))
  logic [BlockW:0]    blocks;     // ceil(size / 4)
  logic [BlockW:0]    blk_next;   // blk + 1

  assign shifted = {coord_i[CoordW-1], coord_i} - (CoordW + 1)'(1 << (Frac - 1));
  assign i0      = {shifted[CoordW], shifted[CoordW:Frac]};
  assign i1      = i0 + IntW'(1);
  assign frac_o  = shifted[Frac-1:0];
  assign last    = IntW'(size_i) - IntW'(1);
  assign t_floor = {{2{coord_i[CoordW-1]}}, coord_i[CoordW-1:Frac]};

  // Clamp of a two's complement value v to 0..last (last <= MaxTexSize - 1).
  // (Assigned to the function name: Yosys 0.23 has no `return`.)
  function automatic logic [TexelW-1:0] clamp_texel(logic [IntW-1:0] v, logic [IntW-1:0] hi);
    if (v[IntW-1]) begin
      clamp_texel = '0;
    end else if (v > hi) begin
      clamp_texel = hi[TexelW-1:0];
    end else begin
      clamp_texel = v[TexelW-1:0];
    end
  endfunction

  assign t0_o = clamp_texel(i0, last);
  assign t1_o = clamp_texel(i1, last);
  assign t    = clamp_texel(t_floor, last);

  assign blocks   = (BlockW + 1)'((size_i + SizeW'(tmu_pkg::CccBlockSide - 1)) >> SubW);
  assign blk_o    = t[TexelW-1:SubW];
  assign blk_next = {1'b0, blk_o} + (BlockW + 1)'(1);
  assign nbr_o    = t[1] ? blk_next[BlockW-1:0] : blk_o - BlockW'(1);
  assign nbr_in_o = t[1] ? (blk_next < blocks) : (blk_o != '0);

  // Bits the arithmetic does not need: the sign of i1 is known from i0, the low bit of t only
  // selects a texel inside the block.
  logic unused_bits;
  assign unused_bits = t[0];

endmodule
