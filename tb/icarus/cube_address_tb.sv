// Icarus testbench of the cube map addressing unit (texsim block cube-map; the fields of
// tb/blocks/cube_map_block.cpp): x y z (SQ2.14) face_log2 -> face, u, v.
module cube_address_tb;
  logic clk_i, rst_ni, in_valid, in_ready, out_valid, out_ready;
  tmu_pkg::unit_comp_t x, y, z;
  tmu_pkg::mip_log2_t  face_log2;
  tmu_pkg::cube_face_t face;
  tmu_pkg::tex_coord_t u, v;

  tmu_cube_address dut (
    .clk_i,
    .rst_ni,
    .in_valid_i    (in_valid),
    .in_ready_o    (in_ready),
    .in_x_i        (x),
    .in_y_i        (y),
    .in_z_i        (z),
    .in_face_log2_i(face_log2),
    .out_valid_o   (out_valid),
    .out_ready_i   (out_ready),
    .out_face_o    (face),
    .out_u_o       (u),
    .out_v_o       (v)
  );

  function automatic bit load_item(input integer fd);
    return $fscanf(fd, "%h %h %h %h\n", x, y, z, face_log2) == 4;
  endfunction
  task automatic clear_item;
    {x, y, z, face_log2} = '0;
  endtask
  task automatic write_output(input integer fd, input longint unsigned cycle);
    $fdisplay(fd, "%0d %h %h %h", cycle, face, u, v);
  endtask

  `include "stream_tb.svh"
endmodule
