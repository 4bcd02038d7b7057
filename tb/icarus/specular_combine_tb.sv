// Icarus testbench of the specular combine (texsim block specular-combine; the fields of
// tb/blocks/specular_combine_block.cpp): diffuse specular reflectance -> colour.
module specular_combine_tb;
  logic clk_i, rst_ni, in_valid, in_ready, out_valid, out_ready;
  tmu_pkg::rgba8888_t diffuse, specular, reflectance, colour;

  tmu_specular_combine dut (
    .clk_i,
    .rst_ni,
    .in_valid_i      (in_valid),
    .in_ready_o      (in_ready),
    .in_diffuse_i    (diffuse),
    .in_specular_i   (specular),
    .in_reflectance_i(reflectance),
    .out_valid_o     (out_valid),
    .out_ready_i     (out_ready),
    .out_colour_o    (colour)
  );

  function automatic bit load_item(input integer fd);
    return $fscanf(fd, "%h %h %h\n", diffuse, specular, reflectance) == 3;
  endfunction
  task automatic clear_item;
    {diffuse, specular, reflectance} = '0;
  endtask
  task automatic write_output(input integer fd, input longint unsigned cycle);
    $fdisplay(fd, "%0d %h", cycle, colour);
  endtask

  `include "stream_tb.svh"
endmodule
