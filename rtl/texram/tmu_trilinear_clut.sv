/// The TEXRAM's colour look-up table (000 §6: "256 entries for R, G, B and opacity alpha
/// (32 bits in total) and acts as an eight-port memory"; Fig. 8, CLUT 814 with address
/// decoder 830): one write port and Ports read ports that read together, each with its
/// own address and a registered output (read data the cycle after re_i).
///
/// A RAM without reset: load every entry a texture uses before sampling it.
module tmu_trilinear_clut #(
  /// Read ports (the eight taps of a trilinear sample).
  parameter int unsigned Ports = 8
) (
  input  logic                       clk_i,
  /// Write: entry waddr_i <= wdata_i.
  input  logic                       we_i,
  input  tmu_pkg::clut_index_t       waddr_i,
  input  tmu_pkg::rgba8888_t         wdata_i,
  /// Read: port p's entry raddr_i[p] to rdata_o[p] (flat, port p at [p * width +: width]).
  input  logic                       re_i,
  input  logic [Ports*tmu_pkg::ClutIndexW-1:0] raddr_i,
  output logic [Ports*tmu_pkg::Rgba8888W-1:0]  rdata_o
);

  localparam int unsigned IW = tmu_pkg::ClutIndexW;
  localparam int unsigned DW = tmu_pkg::Rgba8888W;

  if (Ports < 1 || (1 << IW) != tmu_pkg::ClutEntries) begin : gen_check
    $error("tmu_trilinear_clut: at least one read port; 2^ClutIndexW entries");
  end

  tmu_pkg::rgba8888_t mem_q [tmu_pkg::ClutEntries];

  always_ff @(posedge clk_i) begin
    if (we_i) mem_q[waddr_i] <= wdata_i;
  end

  for (genvar p = 0; p < Ports; p++) begin : gen_port
    tmu_pkg::rgba8888_t rdata_q;
    always_ff @(posedge clk_i) begin
      if (re_i) rdata_q <= mem_q[raddr_i[p*IW +: IW]];
    end
    assign rdata_o[p*DW +: DW] = rdata_q;
  end

endmodule
