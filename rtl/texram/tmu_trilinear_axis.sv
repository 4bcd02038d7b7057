/// The taps of one axis at one level (000 §2), exactly as texram::plan_sample's axis_taps
/// (golden/texram/trilinear.cpp). Combinational.
///
/// The coordinate (SQ16.8, level-0 texels) at level l with SubTexelBits fraction bits is c:
/// bilinear rounds coord / 2^l to them (half up: half a dropped step is added first, so the
/// weights are within half a step of the exact ones), nearest floors it. Bilinear: s = c - 1/2,
/// the first tap t0 = floor(s), the second t0 + 1, the weight of the second = frac(s) as
/// WeightBits bits (its top bits: truncated when S > W, widened with zeros when S < W).
/// Nearest: t0 = floor(c), weight 0. All of it is done on the 8 fraction bits of the port:
/// (coord + half) / 2^l keeps 8 fraction bits, the ones below S are cleared, and the half
/// texel is bit 7 (S >= 1).
///
/// Example: coord = 5.25 (raw 0x540), level 1, S = W = 8, bilinear: c = 2.625, s = 2.125,
/// t0 = 2, weight 0x20. Coord raw 0x541 at level 1: 2.626953.. rounds up to 2.62890625
/// (raw 0x2A1), weight 0x21. Nearest: t0 = 2.
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
  localparam logic [SW-1:0] KeepMask = ~((SW'(1) << Drop) - SW'(1));

  if (SubTexelBits < 1 || SubTexelBits > Frac || WeightBits < 1 || WeightBits > Frac ||
      TapW < SW - Frac + 1) begin : gen_check
    $error("tmu_trilinear_axis: SubTexelBits and WeightBits must be 1..8, TapW >= 18");
  end

  logic [SW-1:0]       half;     // half of the last kept step (bilinear): rounds, not floors
  logic [SW-1:0]       rounded;  // coord + half, one bit wider (it may carry out of SQ16.8)
  logic [SW-1:0]       shifted;  // ... / 2^level, 8 fraction bits
  logic [SW-1:0]       kept;     // ... with the fraction bits below S cleared
  logic [SW-1:0]       s;        // minus half a texel (bilinear)

  // 2^(Drop + level - 1) when something is dropped; Drop + level is at most 7 + 10.
  assign half     = (nearest_i || (Drop == 0 && level_i == '0)) ? '0
                  : SW'(1) << (SW'(Drop) + SW'(level_i) - SW'(1));
  assign rounded  = {coord_i[CW-1], coord_i} + half;
  assign shifted  = $signed(rounded) >>> level_i;
  assign kept     = shifted & KeepMask;
  assign s        = kept - (nearest_i ? SW'(0) : SW'(1) << (Frac - 1));
  assign t0_o     = TapW'($signed(s[SW-1:Frac]));
  assign weight_o = nearest_i ? '0 : s[Frac-1 -: WeightBits];

  if (WeightBits < Frac) begin : gen_unused
    logic unused_bits;
    assign unused_bits = ^s[Frac-WeightBits-1:0];
  end

endmodule
