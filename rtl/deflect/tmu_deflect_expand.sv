/// The deflection unit's expansion step (001 §4.4; golden deflect::expand_phi in
/// golden/deflect/sphere_grid.hpp and DeflectionUnit::deflect, the specification): the
/// first-octant result (l_phi, l_theta) of the map moved back to the octant of the signs
/// (sx, sy, sz), then the yaw + phi_N. Combinational.
///
/// expand_phi takes l, 2Q - l, 2Q + l or 4Q - l (modulo 4Q) for (sx, sz) = (0, 0), (0, 1),
/// (1, 1), (1, 0): the sign of l is sx ^ sz, and 2Q is added when sz. Adding 2Q modulo 4Q
/// flips phi's top bit only, so the whole step is one adder:
///   phi = (phi_N +- l_phi) ^ (sz << (A-1)),  theta = (sy && l_theta != 0, l_theta)
/// (zero is always +0).
///
/// Example (A = 9): sx = 1, sz = 0, l_phi = 20, phi_N = 5: 5 - 20 = -15 = 497 (4Q - 20 + 5).
module tmu_deflect_expand #(
  /// A: bits of phi, 6..12.
  parameter int unsigned PhiBits = 9
) (
  input  logic               sx_i,
  input  logic               sy_i,
  input  logic               sz_i,
  input  logic [PhiBits-2:0] l_phi_i,     // 0 .. Q
  input  logic [PhiBits-3:0] l_theta_i,   // 0 .. Q - 1
  input  logic [PhiBits-1:0] normal_phi_i,
  output logic [PhiBits-1:0] phi_o,
  output logic [PhiBits-2:0] theta_o
);

  localparam int unsigned A = PhiBits;

  logic [A-1:0] l, sum;

  assign l       = A'(l_phi_i);
  assign sum     = (sx_i ^ sz_i) ? normal_phi_i - l : normal_phi_i + l;
  assign phi_o   = {sum[A-1] ^ sz_i, sum[A-2:0]};
  assign theta_o = {sy_i && l_theta_i != '0, l_theta_i};

endmodule
