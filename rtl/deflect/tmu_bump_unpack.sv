/// A bump texel to its angles (001 §4.2; golden deflect::unpack_bump in
/// golden/deflect/bump_map.hpp, the specification). The RGB888 texel `texsim bumpmap` writes
/// holds phi_D in R (bits 7:0) and B bits 6:0 (bits 14:8), |theta_D| in G and theta_D's sign
/// in B bit 7. On the grid A = PhiBits, Q = 2^(A-2):
///   phi_D      = the low A of those 15 bits (phi modulo 4Q);
///   |theta_D|  = min(G, Q - 1): a texel written for a finer grid saturates at the pole;
///   the sign   = B bit 7 unless the magnitude is zero (a texel never gives theta -0).
/// Combinational: the wiring and one comparison in front of tmu_deflect_address.
///
/// Example (A = 9): texel 0x05_8A_81 (R 5, G 138, B 0x81): phi_D = 0x105 = 261, |theta_D| =
/// min(138, 127) = 127, negative: theta_D = -127 (raw 0xFF).
module tmu_bump_unpack #(
  /// A: bits of phi, 6..12 (tmu_deflect's range).
  parameter int unsigned PhiBits = 9
) (
  input  tmu_pkg::rgb888_t           texel_i,
  output logic [PhiBits-1:0]         phi_o,
  output logic [PhiBits-2:0]         theta_o
);

  localparam int unsigned MagBits = PhiBits - 2;

  logic [7:0]         r, g, b;
  logic [14:0]        phi_field;
  logic [MagBits-1:0] mag;

  assign {r, g, b}  = texel_i;
  assign phi_field  = {b[6:0], r};
  assign phi_o      = phi_field[PhiBits-1:0];

  // The bits above phi's A: phi modulo 4Q. Gathered so that lint sees them read.
  logic unused_phi_bits;
  assign unused_phi_bits = ^phi_field[14:PhiBits];

  if (MagBits >= 8) begin : gen_mag_wide
    // Q - 1 >= 255: every G is a magnitude of the grid.
    assign mag = MagBits'(g);
  end else begin : gen_mag_saturate
    assign mag = g[7:MagBits] != '0 ? '1 : g[MagBits-1:0];
  end

  assign theta_o = {b[7] && mag != '0, mag};

endmodule
