/// The volume unit's 3-D marcher (000 §13: "evenly spaced resample locations along an
/// arbitrarily oriented viewing ray"; golden volume::Marcher in golden/volume/marcher.hpp), in
/// the manner of the footprint marcher (tmu_footprint_march): one 26-bit accumulator per axis,
/// loaded with the ray's start and advanced by its step after each location, no multiplier.
///
///   p_0 = start, p_(n+1) = p_n + step   (VoxelPos SQ10.16, two's complement, wrapping)
///
/// Integer addition is exact, so location n is start + n step exactly: no drift however long
/// the ray (the host keeps a ray inside the accumulator's range, golden ray_in_range).
///
/// Timing: a ray is taken when the marcher is idle or hands on its last location in that
/// cycle, so the locations of consecutive rays follow without a gap; its first location is on
/// loc_* the next cycle, then one per clock while loc_ready_i is high. A ray of count 0 is
/// taken and gives no location. Location outputs come straight from the accumulators.
///
/// Example: start x = 1.5 (raw 0x18000), step x = -0.75 (raw -0xC000), count 3: locations
/// 1.5, 0.75, 0.0 (raw 0x18000, 0xC000, 0), the last with loc_last_o.
module tmu_volume_march (
  input  logic                                        clk_i,
  input  logic                                        rst_ni,

  /// A ray: start and step per axis (x at bits [0 +: W], then y, z), its locations.
  input  logic                                        ray_valid_i,
  output logic                                        ray_ready_o,
  input  logic [3*tmu_pkg::VoxelPosW-1:0]             ray_start_i,
  input  logic [3*tmu_pkg::VoxelStepW-1:0]            ray_step_i,
  input  tmu_pkg::voxel_count_t                       ray_count_i,

  /// Locations, x at bits [0 +: VoxelPosW]; last marks a ray's last location.
  output logic                                        loc_valid_o,
  input  logic                                        loc_ready_i,
  output logic [3*tmu_pkg::VoxelPosW-1:0]             loc_pos_o,
  output logic                                        loc_last_o
);

  localparam int unsigned PW = tmu_pkg::VoxelPosW;   // 26
  localparam int unsigned SW = tmu_pkg::VoxelStepW;  // 20
  localparam int unsigned CW = tmu_pkg::VoxelCountW;

  logic                active_q, fire, last, load;
  logic [3*PW-1:0]     pos_q;
  logic [3*SW-1:0]     step_q;
  logic [CW-1:0]       left_q;  // locations after the current one

  assign fire        = active_q && loc_ready_i;
  assign last        = left_q == '0;
  assign ray_ready_o = !active_q || (fire && last);
  assign load        = ray_valid_i && ray_ready_o;
  assign loc_valid_o = active_q;
  assign loc_pos_o   = pos_q;
  assign loc_last_o  = last;

  // The accumulators after a step: each axis wraps modulo 2^26 (the step sign-extended).
  logic [3*PW-1:0] pos_next;
  for (genvar a = 0; a < 3; a++) begin : gen_axis
    assign pos_next[a*PW +: PW] =
        pos_q[a*PW +: PW] + {{(PW - SW){step_q[a*SW + SW - 1]}}, step_q[a*SW +: SW]};
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      active_q <= 1'b0;
    end else if (load) begin
      active_q <= ray_count_i != '0;
    end else if (fire && last) begin
      active_q <= 1'b0;
    end
  end

  // Data registers are read only while a ray is active: no reset.
  always_ff @(posedge clk_i) begin
    if (load) begin
      pos_q  <= ray_start_i;
      step_q <= ray_step_i;
      left_q <= ray_count_i - CW'(1);
    end else if (fire) begin
      pos_q  <= pos_next;
      left_q <= left_q - CW'(1);
    end
  end

endmodule
