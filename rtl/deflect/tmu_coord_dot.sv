/// One dot product of the coordinate generator (001 §5, eq. 17-20, 22; golden eval_coords in
/// golden/deflect/coord_eval.hpp): with W = ValueBits and entries SQ1.(W-1),
///   sum = F1(|theta|) (+-T2(phi mod 2Q)) + (+-T3(|theta|)) 2^(W-1)      exact, 2W - 2 fraction bits
///   dot = (sum + 2^(S-1)) >> S, S = 2W - 2 - 14                         rounded half up to SQ2.14
/// T2 is negated for phi >= 2Q (T2(phi + pi) = -T2(phi)), T3 for theta's sign bit (an odd
/// function; a -0 input negates T3(0) too, as the golden model does). W = 8 needs no rounding.
///
/// Ranges: the write port keeps every entry within +-(2^(W-1) - 1), so the negations are exact
/// in W bits and |sum| <= (2^(W-1) - 1)(2^W - 1) = 2^(2W-1) - 3 2^(W-1) + 1: sum and
/// sum + 2^(S-1) fit 2W bits, and |dot| < 2^15 fits SQ2.14 without saturation (32672 at most
/// for W = 10).
///
/// Example (W = 10): F1 = 511, F2 = 256 with phi < 2Q, F3 = -100 with theta < 0 (negated:
/// +100): sum = 130816 + 51200 = 182016, dot = (182016 + 8) >> 4 = 11376 (0.6943).
module tmu_coord_dot #(
  /// W: bits of a table entry, 8..16.
  parameter int unsigned ValueBits = 10
) (
  input  logic signed [ValueBits-1:0] cos_i,          // F1(|theta|)
  input  logic signed [ValueBits-1:0] phi_entry_i,    // F2, G2 or H2 at phi mod 2Q
  input  logic                        phi_neg_i,      // phi >= 2Q
  input  logic signed [ValueBits-1:0] theta_entry_i,  // F3, G3 or H3 at |theta|
  input  logic                        theta_neg_i,    // theta's sign bit
  output tmu_pkg::unit_comp_t         dot_o
);

  localparam int unsigned W     = ValueBits;
  localparam int unsigned SW    = 2 * W;
  localparam int unsigned Shift = 2 * W - 2 - tmu_pkg::UnitCompFrac;

  if (W < 8 || W > 16 || SW - Shift != tmu_pkg::UnitCompW) begin : gen_check
    $error("tmu_coord_dot: ValueBits must be 8..16");
  end

  logic signed [W-1:0]  phi_term, theta_term;
  logic signed [SW-1:0] sum;

  assign phi_term   = phi_neg_i ? -phi_entry_i : phi_entry_i;
  assign theta_term = theta_neg_i ? -theta_entry_i : theta_entry_i;
  assign sum        = SW'(cos_i) * SW'(phi_term) + (SW'(theta_term) <<< (W - 1));

  if (Shift == 0) begin : gen_exact
    assign dot_o = sum;
  end else begin : gen_round
    assign dot_o = tmu_pkg::UnitCompW'((sum + (SW'(1) << (Shift - 1))) >>> Shift);
  end

endmodule
