/// Fire's shaping table of the material unit (002 §4.2.2; golden perlin::fire_entry in
/// golden/perlin/materials.hpp, the specification): entry k = round(e^(-k/32) 2^12), UQ1.12,
/// k = 0..511, a read-only table of 512 x 13 bits (entry 0 is 4096 = 1.0, entries 289..511
/// are 0).
///
/// The table is built at elaboration by a constant function in integers only (golden uses
/// double exp()): in fixed point with P = 48 fraction bits,
///   E = e^(-1/32) by its series sum_n (-1/32)^n / n!, each term the previous one divided by
///       32 n (floor), twelve terms (the ninth and later are 0 at 48 bits);
///   a_0 = 1, a_(k+1) = round(a_k E) (half up): a_k = e^(-k/32) within 511 x 9 2^-48 < 2^-38;
///   entry k = round(a_k 2^12) half up: (a_k 2^12 + 2^(P-1)) >> P.
/// The exact values e^(-k/32) 2^12 lie at least 0.00107 from a rounding tie (a fraction
/// .5) for every k, and the error above is below 2^-26 there, so every entry is golden's:
/// the block material_fire (tb/blocks/material_fire/) reads all 512 from this module's
/// Verilated model and compares them with fire_entry().
///
/// Example: k = 32 (v = 1.0): e^-1 2^12 = 1506.8, entry 1507.
module tmu_material_fire (
  /// k = floor(v 32) clamped to 0..511 (the caller clamps).
  input  logic [8:0]  in_k_i,
  /// e^(-k/32), UQ1.12.
  output logic [12:0] out_entry_o
);

  localparam int unsigned Entries = 512;
  localparam int unsigned EW      = 13;  // UQ1.12: 0 .. 4096
  localparam int unsigned P       = 48;  // fraction bits of the evaluation
  localparam int unsigned Terms   = 12;  // terms of the series of e^(-1/32)

  // Entry k at [k * EW +: EW].
  function automatic logic [Entries*EW-1:0] build_table();
    logic [127:0] term, e1, acc;
    int unsigned  divisor;
    build_table = '0;
    // E = e^(-1/32) = 1 - 1/32 + 1/(32^2 2!) - ...
    term = 128'(1) << P;
    e1   = '0;
    for (int n = 0; n < Terms; n++) begin
      if (n % 2 == 0) e1 = e1 + term;
      else e1 = e1 - term;
      divisor = 32 * (n + 1);
      term    = term / 128'(divisor);
    end
    // a_k = e^(-k/32), by repeated multiplication with rounding.
    acc = 128'(1) << P;
    for (int k = 0; k < Entries; k++) begin
      build_table[k*EW +: EW] = EW'(((acc << 12) + (128'(1) << (P - 1))) >> P);
      acc = (acc * e1 + (128'(1) << (P - 1))) >> P;
    end
  endfunction

  localparam logic [Entries*EW-1:0] Table = build_table();

  assign out_entry_o = Table[32'(in_k_i)*EW +: EW];

endmodule
