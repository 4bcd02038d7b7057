/// Level selection of the TEXRAM trilinear unit (000 §2): lambda -> the level(s) to read and
/// the level weight, exactly as texram::plan_sample (golden/texram/trilinear.hpp).
/// Combinational.
///
/// lambda (SQ6.8) keeps its top LodFracBits fraction bits (floor): lq. top = max(log2 w,
/// log2 h), the 1 x 1 level.
///   trilinear: lq <= 0 -> level 0 with weight 0 (magnification); lq >= top -> level top,
///              weight 0; else levels floor(lq) and floor(lq) + 1, the weight of the second
///              = the fraction of lq as WeightBits bits (its top bits: truncated when
///              LodFracBits > WeightBits, widened with zeros when fewer).
///   nearest, bilinear: the one level floor(lq + 1/2), clamped to 0..top; weight 0.
/// The second level is read only when its weight is not 0 (two_levels_o).
///
/// Example: top = 6, L = W = 8, lambda = 2.75 (raw 0x2C0): trilinear levels 2 and 3 with
/// weight 0xC0; bilinear level 3. lambda = -0.004 (raw 0x3FFF): level 0, weight 0, both.
module tmu_trilinear_lod #(
  /// Fraction bits of lambda kept (1..8).
  parameter int unsigned LodFracBits = 8,
  /// Bits of the level weight (1..8).
  parameter int unsigned WeightBits  = 8
) (
  /// Level of detail.
  input  tmu_pkg::lod_t        lambda_i,
  /// The top level, max(log2 width, log2 height).
  input  tmu_pkg::mip_log2_t   top_i,
  /// Filter: trilinear (two levels), else nearest or bilinear (one rounded level).
  input  logic                 trilinear_i,
  /// The first level, and the second (level0_o + 1 when two_levels_o, else level0_o).
  output tmu_pkg::mip_level_t  level0_o,
  output tmu_pkg::mip_level_t  level1_o,
  /// Weight of the second level (0 unless trilinear between two levels).
  output logic [WeightBits-1:0] weight_o,
  output logic                 two_levels_o
);

  localparam int unsigned LodW   = tmu_pkg::LodW;     // 14
  localparam int unsigned Frac   = tmu_pkg::LodFrac;  // 8
  localparam int unsigned IntW   = LodW - Frac;       // 6, signed
  localparam int unsigned LevelW = tmu_pkg::MipLevelW;
  localparam int unsigned Drop   = Frac - LodFracBits;
  localparam logic [LodW-1:0] KeepMask = ~((LodW'(1) << Drop) - LodW'(1));

  if (LodFracBits < 1 || LodFracBits > Frac || WeightBits < 1 || WeightBits > Frac ||
      tmu_pkg::MipLog2W != LevelW) begin : gen_check
    $error("tmu_trilinear_lod: LodFracBits and WeightBits must be 1..8");
  end

  logic [LodW-1:0]   lq;          // lambda floored to LodFracBits fraction bits
  logic              negative, zero, at_top;
  logic [IntW:0]     rounded;     // floor(lq + 1/2), two's complement
  logic              rounded_neg, rounded_at_top;
  logic [WeightBits-1:0] frac_w;  // the fraction's top WeightBits bits
  tmu_pkg::mip_level_t level0;

  assign lq       = lambda_i & KeepMask;
  assign negative = lq[LodW-1];
  assign zero     = lq == '0;
  // lq >= top when it is not negative and its integer part is at least top.
  assign at_top   = !negative && (lq[LodW-1:Frac] >= IntW'(top_i));
  assign frac_w   = lq[Frac-1 -: WeightBits];

  assign rounded        = {negative, lq[LodW-1:Frac]} + (IntW + 1)'(lq[Frac-1]);
  assign rounded_neg    = rounded[IntW];
  assign rounded_at_top = !rounded_neg && (rounded[IntW-1:0] >= IntW'(top_i));

  always_comb begin
    if (trilinear_i) begin
      if (negative || zero) begin
        level0   = '0;
        weight_o = '0;
      end else if (at_top) begin
        level0   = top_i;
        weight_o = '0;
      end else begin
        level0   = lq[Frac +: LevelW];
        weight_o = frac_w;
      end
    end else begin
      weight_o = '0;
      if (rounded_neg) begin
        level0 = '0;
      end else if (rounded_at_top) begin
        level0 = top_i;
      end else begin
        level0 = rounded[LevelW-1:0];
      end
    end
  end

  assign two_levels_o = weight_o != '0;
  assign level0_o     = level0;
  assign level1_o     = two_levels_o ? level0 + LevelW'(1) : level0;

endmodule
