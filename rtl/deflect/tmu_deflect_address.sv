/// The deflection unit's address step (001 §4.4 and §6.2; golden deflect::map_address in
/// golden/deflect/s2s_map.hpp, the specification): the roll phi' = phi_D - theta_N, then the
/// octant reduction of (phi', theta') onto the first-octant spherical-to-spherical map.
/// Combinational.
///
/// With A = PhiBits, Q = 2^(A-2) and p = phi' (A bits, modulo 4Q):
///   theta_N is sign and magnitude, so phi' = phi_D - m or phi_D + m (a -0 adds nothing);
///   the top two bits of p name the quadrant and its low A-2 bits lo:
///     0: k = lo       sy = 1, sz = 0      2: k = lo       sy = 0, sz = 1
///     1: k = Q - lo   sy = 1, sz = 1      3: k = Q - lo   sy = 0, sz = 0
///   (sx, sy, sz: the signs of the first-octant vector's x, y, z, set when negative)
///   so an odd quadrant takes Q - lo (2Q - p and 4Q - p), which is Q itself when lo = 0:
///   the z = 0 column (bypass_o), which the map does not store. Otherwise k = -lo modulo Q.
///   sx is theta''s sign bit unless the magnitude is zero (-0 reads as zero), k_theta its
///   magnitude.
/// The block of the map memory is (k_theta >> 2) (Q/4) + (k >> 2), i.e. the two halves'
/// high bits side by side, and the entry in the block (k_theta & 3) 4 + (k & 3).
///
/// Example (A = 9): phi_D = 10, theta_N = +30: p = 10 - 30 = -20 = 492, quadrant 3, lo = 108,
/// k = 20, sy = sz = 0; theta_D = -5: sx = 1, k_theta = 5; block 1 * 32 + 5 = 37, offset
/// 1 * 4 + 0 = 4.
module tmu_deflect_address #(
  /// A: bits of phi (the grid has 2^A x 2^(A-1) patches), 6..12.
  parameter int unsigned PhiBits = 9
) (
  input  logic [PhiBits-1:0]         bump_phi_i,      // phi_D
  input  logic [PhiBits-2:0]         bump_theta_i,    // theta_D = theta': sign, magnitude
  input  logic [PhiBits-2:0]         normal_theta_i,  // theta_N: sign, magnitude

  output logic                       sx_o,            // x < 0: theta' negative
  output logic                       sy_o,            // y < 0: the result's theta negative
  output logic                       sz_o,            // z < 0
  output logic                       bypass_o,        // k = Q: no look-up
  output logic [PhiBits-3:0]         k_theta_o,       // |theta'|
  output logic [2*(PhiBits-4)-1:0]   block_o,         // valid when !bypass_o
  output logic [3:0]                 offset_o         // valid when !bypass_o
);

  localparam int unsigned A       = PhiBits;
  localparam int unsigned MagBits = A - 2;

  logic [A-1:0]       phi_prime;
  logic [A-1:0]       theta_n_mag;
  logic [1:0]         quadrant;
  logic [MagBits-1:0] lo, k;

  assign theta_n_mag = A'(normal_theta_i[MagBits-1:0]);
  // phi_D - theta_N: the sign decides add or subtract; the A-bit result wraps modulo 4Q.
  assign phi_prime   = normal_theta_i[MagBits] ? bump_phi_i + theta_n_mag
                                               : bump_phi_i - theta_n_mag;
  assign quadrant    = phi_prime[A-1 -: 2];
  assign lo          = phi_prime[MagBits-1:0];
  // Odd quadrants mirror: Q - lo, i.e. -lo in MagBits bits (Q itself is the bypass).
  assign k           = quadrant[0] ? -lo : lo;

  assign sx_o      = bump_theta_i[MagBits] && bump_theta_i[MagBits-1:0] != '0;
  assign sy_o      = !quadrant[1];
  assign sz_o      = quadrant[1] ^ quadrant[0];
  assign bypass_o  = quadrant[0] && lo == '0;
  assign k_theta_o = bump_theta_i[MagBits-1:0];
  assign block_o   = {k_theta_o[MagBits-1:2], k[MagBits-1:2]};
  assign offset_o  = {k_theta_o[1:0], k[1:0]};

endmodule
