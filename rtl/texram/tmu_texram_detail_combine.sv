/// A detail sample's colour (000 §9; docs/detail.md), exactly as golden texram::replace_colour,
/// texram::modulate_colour and then texram::combine (eq. 5) with the texture DRF's selection
/// (golden/texram/detail.cpp, trilinear.cpp): the detail colour D, the texture's level-0 texel
/// T (read with eq. 5 "one"), T's weight wt (W bits, 0 at lambda <= -1), per channel with one
/// rounding (half up) each:
///   replace   C = ((2^W - wt) D + wt T + 2^(W-1)) >> W
///   modulate  RGB: P = min(T D, 255 * 128), C = ((2^W - wt) P + wt (T << 7) + 2^(W+6)) >> (W+7);
///             alpha: T's
/// then eq. 5: C ("one"), or round(C M / 255) with M the constant k_T ("constant") or the
/// shade I_d (otherwise, as golden's combine), by tmu_mul255.
/// Combinational; the chip uses the default widths (W = 8).
///
/// Example: replace, wt = 0x40, D red 200, T red 100: (192 * 200 + 64 * 100 + 128) >> 8 = 175.
module tmu_texram_detail_combine #(
  /// The weight's bits (golden Widths::weight), 1..8.
  parameter int unsigned WeightBits = 8
) (
  input  tmu_pkg::rgba8888_t           detail_i,    // D
  input  tmu_pkg::rgba8888_t           texel_i,     // T
  input  logic [WeightBits-1:0]        wt_i,        // T's weight against D
  input  tmu_pkg::tex_detail_combine_t modulate_i,  // 0 replace, 1 modulate
  /// eq. 5 of the texture DRF: the selection (0 one, 1 constant, 2 shade), k_T, I_d.
  input  tmu_pkg::tex_combine_t        combine_i,
  input  tmu_pkg::rgba8888_t           constant_rgba_i,
  input  tmu_pkg::rgba8888_t           shade_i,
  output tmu_pkg::rgba8888_t           rgba_o
);

  localparam int unsigned W   = WeightBits;
  localparam int unsigned CW  = tmu_pkg::ChannelW;  // 8
  localparam int unsigned PF  = 7;                  // T D / 128: 7 fraction bits
  localparam int unsigned PW  = 2 * CW;             // T D, saturated at 255 << 7 (15 bits)
  localparam int unsigned RW  = W + CW + 1;         // replace's sum
  localparam int unsigned MW  = W + PW + 1;         // modulate's sum
  localparam logic [PW-1:0] Saturate = PW'(255) << PF;
  localparam logic [1:0]    CombineOne      = 2'd0;
  localparam logic [1:0]    CombineConstant = 2'd1;

  if (W < 1 || W > 8 || CW != 8 || tmu_pkg::Rgba8888W != 4 * CW) begin : gen_check
    $error("tmu_texram_detail_combine: WeightBits 1..8, 8-bit channels");
  end

  logic [W:0] one_minus;  // 2^W - wt
  assign one_minus = ((W + 1)'(1) << W) - (W + 1)'(wt_i);

  tmu_pkg::rgba8888_t mixed, modulator, scaled;

  // Channel c (0 R .. 3 A) at bits 31 - 8c .. 24 - 8c.
  for (genvar c = 0; c < 4; c++) begin : gen_channel
    logic [CW-1:0] d, t, rep, mod;
    logic [RW-1:0] rep_sum;
    logic [PW-1:0] product, p;
    logic [MW-1:0] mod_sum;
    assign d       = detail_i[(3 - c)*CW +: CW];
    assign t       = texel_i[(3 - c)*CW +: CW];
    assign rep_sum = RW'(one_minus) * RW'(d) + RW'(wt_i) * RW'(t) + (RW'(1) << (W - 1));
    assign rep     = CW'(rep_sum >> W);
    assign product = PW'(t) * PW'(d);
    assign p       = product > Saturate ? Saturate : product;
    assign mod_sum = MW'(one_minus) * MW'(p) + MW'(wt_i) * (MW'(t) << PF) +
                     (MW'(1) << (W + PF - 1));
    assign mod     = CW'(mod_sum >> (W + PF));
    // Modulate keeps T's alpha.
    assign mixed[(3 - c)*CW +: CW] = !modulate_i ? rep : (c == 3 ? t : mod);

    tmu_mul255 u_mul255 (
      .t_i (mixed[(3 - c)*CW +: CW]),
      .m_i (modulator[(3 - c)*CW +: CW]),
      .p_o (scaled[(3 - c)*CW +: CW])
    );

    // The sums' bits above the 8-bit result are 0 by the rules' ranges.
    logic unused_bits;
    assign unused_bits = ^{rep_sum[RW-1:W+CW], mod_sum[MW-1:W+PF+CW]};
  end

  // As golden combine(): "one" keeps C, the constant scales by k_T, anything else by I_d.
  assign modulator = combine_i == CombineConstant ? constant_rgba_i : shade_i;
  assign rgba_o    = combine_i == CombineOne ? mixed : scaled;

endmodule
