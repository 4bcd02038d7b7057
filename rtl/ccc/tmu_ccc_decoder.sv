/// CCC decoder (000 §3, Fig. 5): one texel per clock.
///
/// A request carries a CCC block word and a texel address (4*y + x). The texel's decision
/// bit selects colour index a (bits 31:24) or b (bits 23:16); the index addresses the
/// 256 x RGB888 colour look-up table, whose registered output is the decoded texel.
///
/// The CLUT is written through its own port and is always ready. A request reads the table
/// in the cycle it is accepted, so a write affects requests accepted after it. The CLUT has
/// no reset (it is a RAM): load every entry that will be read.
///
/// Example: block 0x0A0B_0002, texel 1 -> decision bit 1 -> index 0x0B -> CLUT[0x0B].
module tmu_ccc_decoder (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  /// CLUT write port: entry clut_addr_i <= clut_rgb_i when clut_valid_i.
  input  logic                 clut_valid_i,
  output logic                 clut_ready_o,
  input  tmu_pkg::clut_index_t clut_addr_i,
  input  tmu_pkg::rgb888_t     clut_rgb_i,

  /// Decode request.
  input  logic                 req_valid_i,
  output logic                 req_ready_o,
  input  tmu_pkg::ccc_block_t  req_block_i,
  input  tmu_pkg::ccc_texel_t  req_texel_i,

  /// Decoded texel.
  output logic                 out_valid_o,
  input  logic                 out_ready_i,
  output tmu_pkg::rgb888_t     out_rgb_o
);

  tmu_pkg::rgb888_t     clut_q [tmu_pkg::ClutEntries];
  logic                 valid_q;
  tmu_pkg::rgb888_t     rgb_q;
  logic [15:0]          decision_bits;
  logic                 decision;
  tmu_pkg::clut_index_t index;
  logic                 req_fire;

  assign decision_bits = req_block_i[15:0];
  assign decision      = decision_bits[req_texel_i];
  assign index         = decision ? req_block_i[23:16] : req_block_i[31:24];

  // One output register: a new request enters when it is empty or being emptied.
  assign req_ready_o  = !valid_q || out_ready_i;
  assign req_fire     = req_valid_i && req_ready_o;
  assign clut_ready_o = 1'b1;

  always_ff @(posedge clk_i) begin
    if (clut_valid_i) clut_q[clut_addr_i] <= clut_rgb_i;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid_q <= 1'b0;
    end else if (req_ready_o) begin
      valid_q <= req_valid_i;
    end
  end

  // Data needs no reset: it is only observed while valid_q is set.
  always_ff @(posedge clk_i) begin
    if (req_fire) rgb_q <= clut_q[index];
  end

  assign out_valid_o = valid_q;
  assign out_rgb_o   = rgb_q;

endmodule
