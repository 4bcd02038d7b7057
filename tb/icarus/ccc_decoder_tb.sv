// Icarus testbench of the CCC decoder (texsim block ccc; the fields of
// tb/blocks/ccc_decoder_block.cpp): op block texel clut_addr clut_rgb -> rgb. An item with
// op 1 is a CLUT write on the clut channel (no output), op 0 a decode request.
module ccc_decoder_tb;
  logic clk_i, rst_ni, in_valid, in_ready, out_valid, out_ready;
  logic        op;
  tmu_pkg::ccc_block_t  block;
  tmu_pkg::ccc_texel_t  texel;
  tmu_pkg::clut_index_t clut_addr;
  tmu_pkg::rgb888_t     clut_rgb, rgb;
  logic        clut_ready, req_ready;

  // The presented item goes to the channel its op names, the other channel sees zeros.
  tmu_ccc_decoder dut (
    .clk_i,
    .rst_ni,
    .clut_valid_i(in_valid && op),
    .clut_ready_o(clut_ready),
    .clut_addr_i (op ? clut_addr : '0),
    .clut_rgb_i  (op ? clut_rgb : '0),
    .req_valid_i (in_valid && !op),
    .req_ready_o (req_ready),
    .req_block_i (op ? '0 : block),
    .req_texel_i (op ? '0 : texel),
    .out_valid_o (out_valid),
    .out_ready_i (out_ready),
    .out_rgb_o   (rgb)
  );
  assign in_ready = op ? clut_ready : req_ready;

  function automatic bit load_item(input integer fd);
    return $fscanf(fd, "%h %h %h %h %h\n", op, block, texel, clut_addr, clut_rgb) == 5;
  endfunction
  task automatic clear_item;
    {op, block, texel, clut_addr, clut_rgb} = '0;
  endtask
  task automatic write_output(input integer fd, input longint unsigned cycle);
    $fdisplay(fd, "%0d %h", cycle, rgb);
  endtask

  `include "stream_tb.svh"
endmodule
