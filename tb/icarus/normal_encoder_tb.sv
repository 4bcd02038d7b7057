// Icarus testbench of the normal encoder (texsim block normal-encoder; the fields of
// tb/blocks/normal_encoder_block.cpp): x y z (SQ2.14) -> phi, theta. The seed and angle-table
// widths are parameters (iverilog -P), so any --encoder S,E,M runs.
module normal_encoder_tb #(
  parameter int SeedBits = 7,
  parameter int LutExp   = 4,
  parameter int LutMant  = 5
);
  logic clk_i, rst_ni, in_valid, in_ready, out_valid, out_ready;
  tmu_pkg::unit_comp_t  x, y, z;
  tmu_pkg::sphere_phi_t phi;
  tmu_pkg::sphere_theta_t theta;

  tmu_normal_encoder #(
    .SeedBits(SeedBits),
    .LutExp  (LutExp),
    .LutMant (LutMant)
  ) dut (
    .clk_i,
    .rst_ni,
    .in_valid_i (in_valid),
    .in_ready_o (in_ready),
    .in_x_i     (x),
    .in_y_i     (y),
    .in_z_i     (z),
    .out_valid_o(out_valid),
    .out_ready_i(out_ready),
    .out_phi_o  (phi),
    .out_theta_o(theta)
  );

  function automatic bit load_item(input integer fd);
    return $fscanf(fd, "%h %h %h\n", x, y, z) == 3;
  endfunction
  task automatic clear_item;
    {x, y, z} = '0;
  endtask
  task automatic write_output(input integer fd, input longint unsigned cycle);
    $fdisplay(fd, "%0d %h %h", cycle, phi, theta);
  endtask

  `include "stream_tb.svh"
endmodule
