/// The TEXRAM's volume unit (000 §13, Fig. 15; docs/volume.md), bit-exact with the golden
/// model volume::cast (golden/volume/unit.hpp, the specification): a ray in, its resamples
/// out, each from one access of the four level-0 banks per clock.
///
///   march     tmu_volume_march: the ray's locations, start + n step, one per clock
///   corners   per axis (tmu_volume_axis): the location clamped to the volume, i0, the weight
///             of i1 (the top W of its 16 fraction bits) and the corners' flags; registered
///   issue     the access schedule, one access per clock while the memory is ready: 2 per
///             location in value mode (cfg_mode_i 0: the corners of slices k0, k1), 8 in raw
///             mode (then the x-, y- and z-neighbours for the central differences). Per
///             access each of banks 0-3 reads the voxel of its parity ((x & 1) + 2 (y & 1))
///             at the layout's address (tmu_volume_address), or idles where that voxel is
///             outside the volume; every access of the schedule is made, also one that reads
///             nothing (all its voxels outside), so the schedule and its timing are fixed.
///             A location takes an in-flight entry with its first access (none free: it waits)
///   memory    the responses, in request order, fill the entry (access a's four bytes)
///   blend     the oldest complete entry, one pass per clock through one trilinear
///             interpolator (tmu_volume_blend): the value; in raw mode then the gradient's x,
///             y and z components (the patent's "fed through the trilinear interpolator").
///             The last pass loads the output register and frees the entry
/// Throughput: with page hits one location per 2 clocks (value) or 8 (raw), a page fault
/// costing the memory's extra clock; consecutive rays follow without a gap. Latency with
/// page hits: a location's value leaves 4 clocks (value) or 13 (raw) after its first access.
///
/// The configuration (mode, W, the volume's size) is quasi-static: it changes only while the
/// unit is empty. Banks 4-7 are never read: their enables and addresses are 0, their
/// response bytes unused. A bank that idles in an access shows address 0.
module tmu_volume #(
  /// In-flight entries (a power of two, at least 2: two keep one access per clock).
  parameter int unsigned Entries = 2
) (
  input  logic                                      clk_i,
  input  logic                                      rst_ni,

  /// A ray: start and step per axis (x at [0 +: W], then y, z), count resamples.
  input  logic                                      ray_valid_i,
  output logic                                      ray_ready_o,
  input  logic [3*tmu_pkg::VoxelPosW-1:0]           ray_start_i,
  input  logic [3*tmu_pkg::VoxelStepW-1:0]          ray_step_i,
  input  tmu_pkg::voxel_count_t                     ray_count_i,

  /// Configuration (quasi-static): 0 value, 1 raw; W (1..8); the size per axis (2..512).
  input  tmu_pkg::volume_mode_t                     cfg_mode_i,
  input  tmu_pkg::volume_weight_bits_t              cfg_weight_bits_i,
  input  logic [3*tmu_pkg::VolumeSizeW-1:0]         cfg_size_i,

  /// Memory access of the eight banks (0-3 used) and its response, in request order, no
  /// ready: bank b's byte at [8 b +: 8].
  output logic                                      mem_req_valid_o,
  input  logic                                      mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]                 mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  input  logic                                      mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0]               mem_resp_data_i,

  /// A resample: the value, the gradient (x at [0 +: 13], then y, z; 0 in value mode), the
  /// ray's last.
  output logic                                      out_valid_o,
  input  logic                                      out_ready_i,
  output tmu_pkg::channel_t                         out_value_o,
  output logic [3*tmu_pkg::VolumeGradW-1:0]         out_grad_o,
  output tmu_pkg::flag_t                            out_last_o,

  /// Rays taken, resamples given.
  output tmu_pkg::stat_count_t                      stat_rays_o,
  output tmu_pkg::stat_count_t                      stat_resamples_o
);

  localparam int unsigned PW    = tmu_pkg::VoxelPosW;
  localparam int unsigned NW    = tmu_pkg::VolumeSizeW;
  localparam int unsigned AW    = tmu_pkg::BankAddrW;
  localparam int unsigned GW    = tmu_pkg::VolumeGradW;
  localparam int unsigned Banks = tmu_pkg::Banks;
  localparam int unsigned VB    = 4;  // the level-0 banks
  localparam int unsigned PtrW  = $clog2(Entries);
  localparam int unsigned InfoW = 3 * 12;  // per axis {inner2, first, same, i0 parity, w}

  if (Banks != 8 || Entries < 2 || (Entries & (Entries - 1)) != 0 || NW != 10) begin : gen_check
    $error("tmu_volume: built for 8 banks, 10-bit sizes and a power-of-two Entries >= 2");
  end

  logic raw;
  logic [2:0] last_access;
  logic [1:0] last_pass;
  assign raw         = cfg_mode_i != '0;
  assign last_access = raw ? 3'd7 : 3'd1;
  assign last_pass   = raw ? 2'd3 : 2'd0;

  // W's weight bits: the top W of 8.
  logic [7:0] weight_mask;
  assign weight_mask = ~(8'hFF >> cfg_weight_bits_i);

  // Bricks along x and y: ceil(X / 16), ceil(Y / 8).
  logic [NW-1:0] size_x, size_y;
  logic [6:0]    bricks_x;
  logic [7:0]    bricks_y;
  logic [NW:0]   padded_x, padded_y;
  assign size_x   = cfg_size_i[0 +: NW];
  assign size_y   = cfg_size_i[NW +: NW];
  assign padded_x = {1'b0, size_x} + (NW + 1)'(15);
  assign padded_y = {1'b0, size_y} + (NW + 1)'(7);
  assign bricks_x = padded_x[NW:4];
  assign bricks_y = padded_y[NW:3];

  // ---- March ---------------------------------------------------------------------------------

  logic            loc_valid, loc_ready, loc_last;
  logic [3*PW-1:0] loc_pos;

  tmu_volume_march u_march (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .ray_valid_i (ray_valid_i),
    .ray_ready_o (ray_ready_o),
    .ray_start_i (ray_start_i),
    .ray_step_i  (ray_step_i),
    .ray_count_i (ray_count_i),
    .loc_valid_o (loc_valid),
    .loc_ready_i (loc_ready),
    .loc_pos_o   (loc_pos),
    .loc_last_o  (loc_last)
  );

  // ---- Corners -------------------------------------------------------------------------------

  logic [8:0] i0 [3];
  logic [7:0] w [3];
  logic [2:0] same, first, inner2;
  for (genvar a = 0; a < 3; a++) begin : gen_axis
    tmu_volume_axis u_axis (
      .pos_i         (loc_pos[a*PW +: PW]),
      .n_i           (cfg_size_i[a*NW +: NW]),
      .weight_mask_i (weight_mask),
      .i0_o          (i0[a]),
      .w_o           (w[a]),
      .same_o        (same[a]),
      .first_o       (first[a]),
      .inner2_o      (inner2[a])
    );
  end

  logic       c_valid_q, c_last_q, c_load, c_done, mem_fire;
  logic [2:0] acc_q;
  logic [8:0] i0_q [3];
  logic [7:0] w_q [3];
  logic [2:0] same_q, first_q, inner2_q;

  assign mem_fire  = mem_req_valid_o && mem_req_ready_i;
  assign c_done    = mem_fire && acc_q == last_access;
  assign loc_ready = !c_valid_q || c_done;
  assign c_load    = loc_valid && loc_ready;

  // ---- Issue: access acc_q of the schedule ---------------------------------------------------

  // Which pair of x (y) the access reads: the corners i0, i1 or the neighbours i0 - 1, i0 + 2;
  // and its slice: k0 or k1 (accesses 0-5 by their parity), k0 - 1 (6), k0 + 2 (7).
  logic       grad_x, grad_y;
  logic [9:0] z;
  logic       z_in;
  assign grad_x = acc_q[2:1] == 2'b01;
  assign grad_y = acc_q[2:1] == 2'b10;
  always_comb begin
    unique case (acc_q)
      3'd6:    begin z = 10'(i0_q[2]) - 10'd1; z_in = !first_q[2]; end
      3'd7:    begin z = 10'(i0_q[2]) + 10'd2; z_in = inner2_q[2]; end
      default: begin
        z    = 10'(i0_q[2]) + 10'(acc_q[0] && !same_q[2]);
        z_in = 1'b1;
      end
    endcase
  end

  logic [VB-1:0]    bank_en;
  logic [VB*AW-1:0] bank_addr;
  for (genvar b = 0; b < VB; b++) begin : gen_bank
    localparam bit Qx = (b & 1) != 0;  // the bank's x and y parity
    localparam bit Qy = (b & 2) != 0;
    logic       match_x, match_y, x_in, y_in;
    logic [9:0] x, y;
    tmu_pkg::bank_addr_t addr;
    assign match_x = i0_q[0][0] == Qx;
    assign match_y = i0_q[1][0] == Qy;
    // Of a pair, the bank reads the coordinate of its parity: i0 or i0 + 1 (corners), i0 + 2
    // or i0 - 1 (neighbours); i0 + 1 is absent when the axis is clamped (same).
    always_comb begin
      if (grad_x) begin
        x    = match_x ? 10'(i0_q[0]) + 10'd2 : 10'(i0_q[0]) - 10'd1;
        x_in = match_x ? inner2_q[0] : !first_q[0];
      end else begin
        x    = match_x ? 10'(i0_q[0]) : 10'(i0_q[0]) + 10'd1;
        x_in = match_x || !same_q[0];
      end
      if (grad_y) begin
        y    = match_y ? 10'(i0_q[1]) + 10'd2 : 10'(i0_q[1]) - 10'd1;
        y_in = match_y ? inner2_q[1] : !first_q[1];
      end else begin
        y    = match_y ? 10'(i0_q[1]) : 10'(i0_q[1]) + 10'd1;
        y_in = match_y || !same_q[1];
      end
    end
    tmu_volume_address u_address (
      .x_i        (x),
      .y_i        (y),
      .z_i        (z),
      .bricks_x_i (bricks_x),
      .bricks_y_i (bricks_y),
      .addr_o     (addr)
    );
    assign bank_en[b]               = x_in && y_in && z_in;
    assign bank_addr[b*AW +: AW]    = bank_en[b] ? addr : '0;
  end

  // ---- In-flight entries ---------------------------------------------------------------------

  logic [8*32-1:0]      data_q [Entries];
  logic [InfoW:0]       info_q [Entries];  // the axes' info and the ray's last
  logic [Entries-1:0]   done_q;
  logic [PtrW-1:0]      alloc_ptr_q, resp_ptr_q, rd_ptr_q;
  logic [PtrW:0]        count_q;
  logic [2:0]           resp_acc_q;
  logic                 can_alloc, alloc, resp_last, pop;

  assign can_alloc       = count_q != (PtrW + 1)'(Entries);
  assign mem_req_valid_o = c_valid_q && (acc_q != 3'd0 || can_alloc);
  assign alloc           = mem_fire && acc_q == 3'd0;
  assign resp_last       = mem_resp_valid_i && resp_acc_q == last_access;
  assign mem_req_en_o    = {(Banks - VB)'(0), bank_en};
  assign mem_req_addr_o  = {((Banks - VB) * AW)'(0), bank_addr};

  logic [InfoW-1:0] c_info;
  for (genvar a = 0; a < 3; a++) begin : gen_info
    assign c_info[12*a +: 12] = {inner2_q[a], first_q[a], same_q[a], i0_q[a][0], w_q[a]};
  end

  // ---- Blend ---------------------------------------------------------------------------------

  logic                  head_done, out_free, blend_go;
  logic [1:0]            pass_q;
  logic [InfoW:0]        head_info;
  tmu_pkg::channel_t     pass_value;
  tmu_pkg::volume_grad_t pass_grad;
  tmu_pkg::channel_t     res_value_q;
  tmu_pkg::volume_grad_t res_gx_q, res_gy_q;
  logic                  out_valid_q, out_last_q;
  tmu_pkg::channel_t     out_value_q;
  logic [3*GW-1:0]       out_grad_q;
  tmu_pkg::stat_count_t  rays_q, resamples_q;

  assign head_done = count_q != '0 && done_q[rd_ptr_q];
  assign head_info = info_q[rd_ptr_q];
  assign out_free  = !out_valid_q || out_ready_i;
  // A pass runs when the head is complete; the last one also needs the output register.
  assign blend_go  = head_done && (pass_q != last_pass || out_free);
  assign pop       = blend_go && pass_q == last_pass;

  tmu_volume_blend u_blend (
    .data_i  (data_q[rd_ptr_q]),
    .info_i  (head_info[InfoW-1:0]),
    .pass_i  (pass_q),
    .value_o (pass_value),
    .grad_o  (pass_grad)
  );

  assign out_valid_o      = out_valid_q;
  assign out_value_o      = out_value_q;
  assign out_grad_o       = out_grad_q;
  assign out_last_o       = out_last_q;
  assign stat_rays_o      = rays_q;
  assign stat_resamples_o = resamples_q;

  // ---- Flops ---------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      c_valid_q   <= 1'b0;
      acc_q       <= 3'd0;
      alloc_ptr_q <= '0;
      resp_ptr_q  <= '0;
      rd_ptr_q    <= '0;
      count_q     <= '0;
      resp_acc_q  <= 3'd0;
      done_q      <= '0;
      pass_q      <= 2'd0;
      out_valid_q <= 1'b0;
      rays_q      <= '0;
      resamples_q <= '0;
    end else begin
      c_valid_q   <= c_load || (c_valid_q && !c_done);
      if (mem_fire) acc_q <= c_done ? 3'd0 : acc_q + 3'd1;
      alloc_ptr_q <= alloc_ptr_q + PtrW'(alloc);
      resp_ptr_q  <= resp_ptr_q + PtrW'(resp_last);
      rd_ptr_q    <= rd_ptr_q + PtrW'(pop);
      count_q     <= count_q + (PtrW + 1)'(alloc) - (PtrW + 1)'(pop);
      if (mem_resp_valid_i) resp_acc_q <= resp_last ? 3'd0 : resp_acc_q + 3'd1;
      if (alloc) done_q[alloc_ptr_q] <= 1'b0;
      if (resp_last) done_q[resp_ptr_q] <= 1'b1;
      if (blend_go) pass_q <= pop ? 2'd0 : pass_q + 2'd1;
      out_valid_q <= pop || (out_valid_q && !out_ready_i);
      rays_q      <= rays_q + 32'(ray_valid_i && ray_ready_o);
      resamples_q <= resamples_q + 32'(pop);
    end
  end

  // Data registers are read only while their stage, entry or pass is valid: no reset.
  always_ff @(posedge clk_i) begin
    if (c_load) begin
      for (int a = 0; a < 3; a++) begin
        i0_q[a] <= i0[a];
        w_q[a]  <= w[a];
      end
      same_q   <= same;
      first_q  <= first;
      inner2_q <= inner2;
      c_last_q <= loc_last;
    end
  end

  always_ff @(posedge clk_i) begin
    if (alloc) info_q[alloc_ptr_q] <= {c_last_q, c_info};
  end

  always_ff @(posedge clk_i) begin
    if (mem_resp_valid_i) data_q[resp_ptr_q][32*resp_acc_q +: 32] <= mem_resp_data_i[0 +: 32];
  end

  always_ff @(posedge clk_i) begin
    if (blend_go && !pop) begin
      unique case (pass_q)
        2'd0:    res_value_q <= pass_value;
        2'd1:    res_gx_q    <= pass_grad;
        default: res_gy_q    <= pass_grad;
      endcase
    end
  end

  always_ff @(posedge clk_i) begin
    if (pop) begin
      out_value_q <= raw ? res_value_q : pass_value;
      out_grad_q  <= raw ? {pass_grad, res_gy_q, res_gx_q} : '0;
      out_last_q  <= head_info[InfoW];
    end
  end

  logic unused_bits;
  assign unused_bits = ^{mem_resp_data_i[Banks*8-1:32], padded_x[3:0], padded_y[2:0]};

  // ---- Assertions ----------------------------------------------------------------------------
  // They run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions and
  // defines SYNTHESIS.
`ifndef SYNTHESIS
  // The memory answers only accesses it accepted (an assumption on the environment).
  logic [PtrW+4:0] pending_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      pending_q <= '0;
    end else begin
      pending_q <= pending_q + (PtrW + 5)'(mem_fire) - (PtrW + 5)'(mem_resp_valid_i);
    end
  end
  property p_resp_expected;
    @(posedge clk_i) disable iff (!rst_ni) mem_resp_valid_i |-> pending_q != '0;
  endproperty
  a_resp_expected: assert property (p_resp_expected);

  // The entries never hold more than there are; the banks 4-7 are never read.
  property p_entries_bound;
    @(posedge clk_i) disable iff (!rst_ni) count_q <= (PtrW + 1)'(Entries);
  endproperty
  a_entries_bound: assert property (p_entries_bound);
  property p_level0_banks;
    @(posedge clk_i) disable iff (!rst_ni) mem_req_valid_o |-> mem_req_en_o[Banks-1:VB] == '0;
  endproperty
  a_level0_banks: assert property (p_level0_banks);
`endif

endmodule
