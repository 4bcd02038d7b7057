/// One axis of the trilinear unit's sphere-map addressing (golden texram::texel_request in
/// golden/texram/trilinear.hpp, the specification): a sphere map's coordinate c = uN or vN
/// (UnitComp SQ2.14: the coordinate port's low 16 bits, the bits above ignored) to the
/// TexCoord texel coordinate of a level 0 of 2^log2 texels:
///   u = (c + 1) / 2 * 2^log2 (flip_i = 0),  v = (1 - c) / 2 * 2^log2 (flip_i = 1, v runs down
///   the rows); raw: (2^14 +- c) << (log2 - 7), or >> (7 - log2) with floor below 128 texels.
/// At most 17 bits before the shift, 20 after it (log2 <= 10): no overflow. Combinational:
/// one adder and a shifter in front of the request register.
///
/// Example: c = -0.25 (raw -4096), log2 = 8 (256 texels): u = 0.375 * 256 = 96 texels, raw
/// (16384 - 4096) << 1 = 24576 = 96.0 in SQ16.8.
module tmu_trilinear_sphere (
  input  tmu_pkg::tex_coord_t  coord_i,
  input  logic                 flip_i,
  input  tmu_pkg::mip_log2_t   log2_i,
  output tmu_pkg::tex_coord_t  coord_o
);

  localparam int unsigned CW    = tmu_pkg::UnitCompW;  // 16
  localparam int unsigned TW    = tmu_pkg::TexCoordW;  // 24
  // texels = (1 +- c) / 2 * 2^log2: the SQ.14 sum becomes SQ.8 texels by a shift of log2 - 7.
  localparam int unsigned Shift = tmu_pkg::UnitCompFrac + 1 - tmu_pkg::TexCoordFrac;  // 7

  localparam tmu_pkg::mip_log2_t ShiftLog2 = tmu_pkg::MipLog2W'(Shift);

  if (CW != 16 || Shift != 7 || TW != 24) begin : gen_check_formats
    $error("tmu_trilinear_sphere: built for UnitComp SQ2.14 and TexCoord SQ16.8");
  end

  logic signed [CW:0]   c, one, half_turns;
  logic signed [TW-1:0] wide;

  assign c          = {coord_i[CW-1], coord_i[CW-1:0]};
  assign one        = (CW+1)'(1) <<< tmu_pkg::UnitCompFrac;
  assign half_turns = flip_i ? one - c : one + c;
  assign wide       = {{(TW - CW - 1){half_turns[CW]}}, half_turns};
  assign coord_o    = log2_i >= ShiftLog2 ? wide <<< (log2_i - ShiftLog2)
                                          : wide >>> (ShiftLog2 - log2_i);

endmodule
