/// round(t m / 255) for two 8-bit channels, exactly as golden texram::mul255
/// (golden/texram/trilinear.hpp): x = t m + 128, then (x + (x >> 8)) >> 8. Combinational;
/// the RTL's one copy of it (tmu_trilinear_blend's eq. 5 stage, tmu_specular_combine).
///
/// 16 bits suffice: x <= 255 * 255 + 128 = 65153 and x + (x >> 8) <= 65407.
///
/// Example: t = 200, m = 100: x = 20128, x >> 8 = 78, (20128 + 78) >> 8 = 78
/// (200 * 100 / 255 = 78.43).
module tmu_mul255 (
  input  tmu_pkg::channel_t t_i,
  input  tmu_pkg::channel_t m_i,
  output tmu_pkg::channel_t p_o
);

  localparam int unsigned ChW = tmu_pkg::ChannelW;

  if (ChW != 8) begin : gen_check
    $error("tmu_mul255: built for 8-bit channels");
  end

  logic [2*ChW-1:0] x, y;

  assign x   = (2 * ChW)'(t_i) * (2 * ChW)'(m_i) + (2 * ChW)'(128);
  assign y   = x + (x >> ChW);
  assign p_o = ChW'(y >> ChW);

endmodule
