// Icarus testbench of the noise unit (texsim block perlin; the fields of
// tb/blocks/perlin_block.cpp): u v w (SQ12.12) -> p.
module noise_tb;
  logic clk_i, rst_ni, in_valid, in_ready, out_valid, out_ready;
  tmu_pkg::solid_coord_t u, v, w;
  tmu_pkg::noise_value_t p;

  tmu_noise dut (
    .clk_i,
    .rst_ni,
    .in_valid_i (in_valid),
    .in_ready_o (in_ready),
    .in_u_i     (u),
    .in_v_i     (v),
    .in_w_i     (w),
    .out_valid_o(out_valid),
    .out_ready_i(out_ready),
    .out_p_o    (p)
  );

  function automatic bit load_item(input integer fd);
    return $fscanf(fd, "%h %h %h\n", u, v, w) == 3;
  endfunction
  task automatic clear_item;
    {u, v, w} = '0;
  endtask
  task automatic write_output(input integer fd, input longint unsigned cycle);
    $fdisplay(fd, "%0d %h", cycle, p);
  endtask

  `include "stream_tb.svh"
endmodule
