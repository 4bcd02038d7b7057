/// The taps of one axis at one level (000 §2), exactly as texram::plan_sample's axis_taps
/// (golden/texram/trilinear.cpp). Combinational.
///
/// The coordinate (SQ16.8, level-0 texels) at level l is floor(coord / 2^l) with SubTexelBits
/// fraction bits: c. Bilinear: s = c - 1/2, the first tap t0 = floor(s), the second t0 + 1,
/// the weight of the second = frac(s) as WeightBits bits (its top bits: truncated when
/// S > W, widened with zeros when S < W). Nearest: t0 = floor(c), weight 0.
/// All of it is done on the 8 fraction bits of the port: floor(coord / 2^l) keeps 8 fraction
/// bits, the ones below S are cleared, and the half texel is bit 7 (S >= 1).
///
/// Example: coord = 5.25 (raw 0x540), level 1, S = W = 8, bilinear: c = 2.625, s = 2.125,
/// t0 = 2, weight 0x20. Nearest: t0 = 2.
module tmu_trilinear_axis #(
  /// Fraction bits of a coordinate within a level (1..8).
  parameter int unsigned SubTexelBits = 8,
  /// Bits of the filter weight (1..8).
  parameter int unsigned WeightBits   = 8,
  /// Width of the tap coordinate (two's complement); 18 holds every port value's taps.
  parameter int unsigned TapW         = 18
) (
  input  tmu_pkg::tex_coord_t  coord_i,
  input  tmu_pkg::mip_level_t  level_i,
  input  logic                 nearest_i,
  /// The first tap, unresolved (before the border operator), in texels of the level.
  output logic [TapW-1:0]      t0_o,
  /// Weight of the second tap t0 + 1.
  output logic [WeightBits-1:0] weight_o
);

  localparam int unsigned CW   = tmu_pkg::TexCoordW;     // 24
  localparam int unsigned Frac = tmu_pkg::TexCoordFrac;  // 8
  localparam int unsigned SW   = CW + 1;                 // room for minus half a texel
  localparam int unsigned Drop = Frac - SubTexelBits;
  localparam logic [CW-1:0] KeepMask = ~((CW'(1) << Drop) - CW'(1));

  if (SubTexelBits < 1 || SubTexelBits > Frac || WeightBits < 1 || WeightBits > Frac ||
      TapW < SW - Frac + 1) begin : gen_check
    $error("tmu_trilinear_axis: SubTexelBits and WeightBits must be 1..8, TapW >= 18");
  end

  tmu_pkg::tex_coord_t shifted;  // floor(coord / 2^level), 8 fraction bits
  logic [CW-1:0]       kept;     // ... with the fraction bits below S cleared
  logic [SW-1:0]       s;        // minus half a texel (bilinear)

  assign shifted  = coord_i >>> level_i;
  assign kept     = shifted & KeepMask;
  assign s        = {kept[CW-1], kept} - (nearest_i ? SW'(0) : SW'(1) << (Frac - 1));
  assign t0_o     = TapW'($signed(s[SW-1:Frac]));
  assign weight_o = nearest_i ? '0 : s[Frac-1 -: WeightBits];

  if (WeightBits < Frac) begin : gen_unused
    logic unused_bits;
    assign unused_bits = ^s[Frac-WeightBits-1:0];
  end

endmodule
