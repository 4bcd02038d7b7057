/// The TEXRAM's access and colour stages (000 §2, §5, §6; Fig. 8: banks 810, CLUT 814, the
/// tri-linear interpolator 818, output and combination 820), behind an address unit that has
/// planned a sample: each of its eight taps' read flag, bank and cell, and the entry
/// information (per tap: outside, bank, texel in its CCC block; the weights; the shade). The
/// trilinear unit (tmu_trilinear) and the clip-map unit (tmu_clipmap) put their own address
/// stages in front of it; golden texram::read_access, tap_colour, blend_taps and combine
/// (golden/texram/trilinear.hpp) are the specification.
///
///   S5 issue   per bank: read enable and address, the cell of the lowest-numbered tap that
///              reads the bank (taps of one bank share one cell whenever the layout holds;
///              otherwise the others read that cell: the clip-map's rule for tiles that are
///              not nested, golden clipmap::plan_clip_sample; FirstTapWins). One access per byte plane,
///              plane p at address + p. Each sample takes an entry of the in-flight buffer
///              (InFlight entries) when its first access is accepted (at once when it reads
///              nothing); no entry free: it waits.
///   memory     the access's response (request order, no ready) is written into the entry:
///              planes 0..2 are gathered, the last completes the entry
///   T  texel   the oldest complete entry: per tap, its bank's bytes -> colour or CLUT index
///              (tmu_trilinear_texel); the eight CLUT reads (tmu_trilinear_clut)
///   X, Y, Z, O the blend and eq. 5 (tmu_trilinear_blend), then the output register
/// With a page hit (response the cycle after the access is accepted) the output is valid 7
/// cycles after the sample entered S5. One sample per clock for one-plane textures while the
/// pages hit (a fault costs a clock), four clocks for four planes.
///
/// The information word (InfoW bits, laid out as the caller builds it): tap t's
/// {outside, bank, ty, tx} at [t * 8 +: 8], then wx (2 W), wy (2 W), wl (W) and the shade.
///
/// The CLUT is a RAM without reset, written through clut_we_i; the caller writes it only while
/// busy_o is low and no sample is in front of this stage, so a write is ordered with the samples.
module tmu_texram_access #(
  /// Filter and level weight bits, 1..8.
  parameter int unsigned WeightBits = 8,
  /// Samples between issue and the texel stage.
  parameter int unsigned InFlight   = 4,
  /// Taps of one bank on different cells: 1, the lowest-numbered tap decides the bank's cell
  /// (the clip-map's rule); 0, the cells are ORed (a layout that never puts two cells of a
  /// sample in one bank, the trilinear unit's: no priority logic).
  parameter bit          FirstTapWins = 1'b1
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  /// Configuration (quasi-static): the texel kind (decoded; none set: luminance), the output
  /// channel of a single-component texture, the border colour, eq. 5.
  input  logic                       kind_index_i,
  input  logic                       kind_true_colour_i,
  input  logic                       kind_single_i,
  input  logic                       kind_ccc_i,
  input  tmu_pkg::byte_plane_t       single_channel_i,
  input  tmu_pkg::rgba8888_t         border_rgba_i,
  input  logic                       combine_constant_i,
  input  logic                       combine_shade_i,
  input  tmu_pkg::rgba8888_t         constant_rgba_i,

  /// A planned sample.
  input  logic                       in_valid_i,
  output logic                       in_ready_o,
  input  logic [7:0]                 in_read_i,
  input  logic [8*3-1:0]             in_bank_i,
  input  logic [8*tmu_pkg::BankAddrW-1:0] in_addr_i,
  input  logic [8*8 + 5*WeightBits + tmu_pkg::Rgba8888W - 1:0] in_info_i,

  /// CLUT write (see above), and whether a sample is between S5 and the texel stage.
  input  logic                       clut_we_i,
  input  tmu_pkg::clut_index_t       clut_addr_i,
  input  tmu_pkg::rgba8888_t         clut_rgba_i,
  output logic                       busy_o,

  /// Memory access and its response (as tmu_trilinear's ports).
  output logic                       mem_req_valid_o,
  input  logic                       mem_req_ready_i,
  output logic [tmu_pkg::Banks-1:0]  mem_req_en_o,
  output logic [tmu_pkg::Banks*tmu_pkg::BankAddrW-1:0] mem_req_addr_o,
  input  logic                       mem_resp_valid_i,
  input  logic [tmu_pkg::Banks*8-1:0] mem_resp_data_i,

  /// The sample, RGBA8888, in order.
  output logic                       out_valid_o,
  input  logic                       out_ready_i,
  output tmu_pkg::rgba8888_t         out_rgba_o
);

  localparam int unsigned W         = WeightBits;
  localparam int unsigned Banks     = tmu_pkg::Banks;
  localparam int unsigned Taps      = 8;
  localparam int unsigned AddrW     = tmu_pkg::BankAddrW;
  localparam int unsigned CW        = tmu_pkg::Rgba8888W;
  localparam int unsigned PtrW      = $clog2(InFlight);
  localparam int unsigned DataW     = tmu_pkg::Planes * Banks * 8;
  localparam int unsigned TapInfoW  = 1 + tmu_pkg::BankW + 4;
  localparam int unsigned InfoTaps  = 0;
  localparam int unsigned InfoWx    = Taps * TapInfoW;
  localparam int unsigned InfoWy    = InfoWx + 2 * W;
  localparam int unsigned InfoWl    = InfoWy + 2 * W;
  localparam int unsigned InfoShade = InfoWl + W;
  localparam int unsigned InfoW     = InfoShade + CW;

  if (Banks != 8 || tmu_pkg::Planes != 4 || tmu_pkg::BankW != 3 || TapInfoW != 8 ||
      InFlight < 2 || (InFlight & (InFlight - 1)) != 0) begin : gen_check
    $error("tmu_texram_access: built for 8 banks, 4 planes and a power-of-two InFlight");
  end

  logic four_planes;
  logic [1:0] last_plane;
  assign four_planes = kind_true_colour_i || kind_ccc_i;
  assign last_plane  = four_planes ? 2'd3 : 2'd0;

  // ---- S5: the access ---------------------------------------------------------------------

  // Per bank: read by any tap, at the lowest-numbered such tap's address (or their OR).
  logic [Banks-1:0]       bank_en;
  logic [Banks*AddrW-1:0] bank_addr;
  always_comb begin
    bank_en   = '0;
    bank_addr = '0;
    for (int b = 0; b < Banks; b++) begin
      for (int t = Taps - 1; t >= 0; t--) begin
        if (in_read_i[t] && in_bank_i[t*3 +: 3] == 3'(b)) begin
          bank_en[b]                  = 1'b1;
          bank_addr[b*AddrW +: AddrW] = FirstTapWins ? in_addr_i[t*AddrW +: AddrW]
              : bank_addr[b*AddrW +: AddrW] | in_addr_i[t*AddrW +: AddrW];
        end
      end
    end
  end

  logic                   s5_valid_q, s5_leave, s5_load;
  logic [Banks-1:0]       s5_en_q;
  logic [Banks*AddrW-1:0] s5_addr_q;
  logic [InfoW-1:0]       s5_info_q;
  logic [1:0]             plane_q, plane_d;

  assign in_ready_o = !s5_valid_q || s5_leave;
  assign s5_load    = in_valid_i && in_ready_o;

  // ---- In-flight buffer -----------------------------------------------------------------------

  logic [InfoW-1:0]  info_q [InFlight];
  logic [DataW-1:0]  data_q [InFlight];
  logic [InFlight-1:0] done_q, done_d;        // the entry's bytes are all there
  logic [PtrW-1:0]   alloc_ptr_q, rd_ptr_q;
  logic [PtrW:0]     alloc_count_q, alloc_count_d;
  // Entries awaiting a response, oldest first.
  logic [PtrW-1:0]   resp_entry_q [InFlight];
  logic [PtrW-1:0]   resp_wr_q, resp_rd_q;
  logic [1:0]        resp_plane_q;
  logic [63:0]       gather_q [3];

  logic              has_reads, can_alloc, mem_fire, alloc, resp_last, pop, t_ready;
  logic [PtrW-1:0]   resp_entry;

  assign has_reads = s5_en_q != '0;
  assign can_alloc = alloc_count_q != (PtrW + 1)'(InFlight);
  assign mem_req_valid_o = s5_valid_q && has_reads && (plane_q != 2'd0 || can_alloc);
  assign mem_fire  = mem_req_valid_o && mem_req_ready_i;
  // The sample takes its entry with its first access, or at once when it reads nothing.
  assign alloc     = has_reads ? mem_fire && plane_q == 2'd0 : s5_valid_q && can_alloc;
  assign s5_leave  = has_reads ? mem_fire && plane_q == last_plane : s5_valid_q && can_alloc;
  assign plane_d   = mem_fire ? (plane_q == last_plane ? 2'd0 : plane_q + 2'd1) : plane_q;
  assign busy_o    = s5_valid_q || alloc_count_q != '0;

  assign mem_req_en_o = s5_en_q;
  for (genvar b = 0; b < Banks; b++) begin : gen_mem_addr
    // Four planes: the base address is a multiple of 4, plane p is base + p.
    assign mem_req_addr_o[b*AddrW +: AddrW] =
        four_planes ? {s5_addr_q[b*AddrW + 2 +: AddrW - 2], plane_q} : s5_addr_q[b*AddrW +: AddrW];
  end

  assign resp_entry = resp_entry_q[resp_rd_q];
  assign resp_last  = mem_resp_valid_i && resp_plane_q == last_plane;

  logic head_done;
  assign head_done     = alloc_count_q != '0 && done_q[rd_ptr_q];
  assign pop           = head_done && t_ready;
  assign alloc_count_d = alloc_count_q + (PtrW + 1)'(alloc) - (PtrW + 1)'(pop);

  always_comb begin
    done_d = done_q;
    if (alloc) done_d[alloc_ptr_q] = !has_reads;
    if (resp_last) done_d[resp_entry] = 1'b1;
  end

  // ---- T: texels and CLUT -----------------------------------------------------------------

  logic [InfoW-1:0]     head_info;
  logic [DataW-1:0]     head_data;
  logic [Taps*CW-1:0]   texel_colour;
  logic [Taps-1:0]      texel_use_clut;
  logic [Taps*8-1:0]    texel_clut_index;

  assign head_info = info_q[rd_ptr_q];
  assign head_data = data_q[rd_ptr_q];

  for (genvar t = 0; t < Taps; t++) begin : gen_texel
    logic [TapInfoW-1:0] info;
    tmu_pkg::bank_t      bank;
    tmu_pkg::rgba8888_t  bytes;
    assign info = head_info[InfoTaps + t*TapInfoW +: TapInfoW];
    assign bank = info[6:4];
    for (genvar p = 0; p < 4; p++) begin : gen_plane  // plane p in byte 3 - p
      assign bytes[(3 - p)*8 +: 8] = head_data[p*Banks*8 + 8*32'(bank) +: 8];
    end
    tmu_trilinear_texel u_texel (
      .bytes_i          (bytes),
      .outside_i        (info[7]),
      .tx_i             (info[1:0]),
      .ty_i             (info[3:2]),
      .index_i          (kind_index_i),
      .true_colour_i    (kind_true_colour_i),
      .single_i         (kind_single_i),
      .ccc_i            (kind_ccc_i),
      .single_channel_i (single_channel_i),
      .border_rgba_i    (border_rgba_i),
      .colour_o         (texel_colour[t*CW +: CW]),
      .use_clut_o       (texel_use_clut[t]),
      .clut_index_o     (texel_clut_index[t*8 +: 8])
    );
  end

  logic                 t_valid_q;
  logic [Taps*CW-1:0]   clut_rdata;
  logic [Taps*CW-1:0]   t_colour_q;
  logic [Taps-1:0]      t_use_clut_q;
  logic [2*W-1:0]       t_wx_q, t_wy_q;
  logic [W-1:0]         t_wl_q;
  tmu_pkg::rgba8888_t   t_shade_q;
  logic                 blend_ready;

  tmu_trilinear_clut #(.Ports(Taps)) u_clut (
    .clk_i   (clk_i),
    .we_i    (clut_we_i),
    .waddr_i (clut_addr_i),
    .wdata_i (clut_rgba_i),
    .re_i    (pop),
    .raddr_i (texel_clut_index),
    .rdata_o (clut_rdata)
  );

  assign t_ready = !t_valid_q || blend_ready;

  logic [Taps*CW-1:0] colours;
  for (genvar t = 0; t < Taps; t++) begin : gen_colour
    assign colours[t*CW +: CW] = t_use_clut_q[t] ? clut_rdata[t*CW +: CW] : t_colour_q[t*CW +: CW];
  end

  // ---- X, Y, Z, O: blend and eq. 5 ----------------------------------------------------------

  tmu_trilinear_blend #(.WeightBits(W)) u_blend (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .combine_constant_i (combine_constant_i),
    .combine_shade_i    (combine_shade_i),
    .constant_rgba_i    (constant_rgba_i),
    .in_valid_i         (t_valid_q),
    .in_ready_o         (blend_ready),
    .in_colours_i       (colours),
    .in_wx_i            (t_wx_q),
    .in_wy_i            (t_wy_q),
    .in_wl_i            (t_wl_q),
    .in_shade_i         (t_shade_q),
    .out_valid_o        (out_valid_o),
    .out_ready_i        (out_ready_i),
    .out_rgba_o         (out_rgba_o)
  );

  // ---- Flops --------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s5_valid_q    <= 1'b0;
      plane_q       <= 2'd0;
      alloc_ptr_q   <= '0;
      rd_ptr_q      <= '0;
      alloc_count_q <= '0;
      done_q        <= '0;
      resp_wr_q     <= '0;
      resp_rd_q     <= '0;
      resp_plane_q  <= 2'd0;
      t_valid_q     <= 1'b0;
    end else begin
      s5_valid_q    <= s5_load || (s5_valid_q && !s5_leave);
      plane_q       <= plane_d;
      alloc_ptr_q   <= alloc_ptr_q + PtrW'(alloc);
      rd_ptr_q      <= rd_ptr_q + PtrW'(pop);
      alloc_count_q <= alloc_count_d;
      done_q        <= done_d;
      resp_wr_q     <= resp_wr_q + PtrW'(alloc && has_reads);
      resp_rd_q     <= resp_rd_q + PtrW'(resp_last);
      if (mem_resp_valid_i) resp_plane_q <= resp_last ? 2'd0 : resp_plane_q + 2'd1;
      t_valid_q     <= pop || (t_valid_q && !blend_ready);
    end
  end

  // Data registers are read only while their stage (or entry) is valid: no reset.
  always_ff @(posedge clk_i) begin
    if (s5_load) begin
      s5_en_q   <= bank_en;
      s5_addr_q <= bank_addr;
      s5_info_q <= in_info_i;
    end
  end

  always_ff @(posedge clk_i) begin
    if (alloc) info_q[alloc_ptr_q] <= s5_info_q;
  end

  always_ff @(posedge clk_i) begin
    if (alloc && has_reads) resp_entry_q[resp_wr_q] <= alloc_ptr_q;
  end

  always_ff @(posedge clk_i) begin
    if (mem_resp_valid_i && !resp_last) gather_q[resp_plane_q] <= mem_resp_data_i;
  end

  // The last plane completes the entry: planes 0..3 at [p * 64 +: 64] (one plane: plane 0).
  always_ff @(posedge clk_i) begin
    if (resp_last) begin
      data_q[resp_entry] <= {mem_resp_data_i, gather_q[2], gather_q[1],
                             four_planes ? gather_q[0] : mem_resp_data_i};
    end
  end

  always_ff @(posedge clk_i) begin
    if (pop) begin
      t_colour_q   <= texel_colour;
      t_use_clut_q <= texel_use_clut;
      t_wx_q       <= head_info[InfoWx +: 2*W];
      t_wy_q       <= head_info[InfoWy +: 2*W];
      t_wl_q       <= head_info[InfoWl +: W];
      t_shade_q    <= head_info[InfoShade +: CW];
    end
  end

  // ---- Assertions ---------------------------------------------------------------------------
  // They run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions and
  // defines SYNTHESIS.
`ifndef SYNTHESIS
  // Every access reads at least one bank.
  property p_mem_req_reads;
    @(posedge clk_i) disable iff (!rst_ni) mem_req_valid_o |-> mem_req_en_o != '0;
  endproperty
  a_mem_req_reads: assert property (p_mem_req_reads);

  // The memory answers only accesses it accepted (an assumption on the environment).
  logic [PtrW+3:0] accesses_pending_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      accesses_pending_q <= '0;
    end else begin
      accesses_pending_q <= accesses_pending_q + (PtrW + 4)'(mem_fire) -
                            (PtrW + 4)'(mem_resp_valid_i);
    end
  end
  property p_resp_expected;
    @(posedge clk_i) disable iff (!rst_ni) mem_resp_valid_i |-> accesses_pending_q != '0;
  endproperty
  a_resp_expected: assert property (p_resp_expected);

  // The in-flight buffer never holds more than its entries.
  property p_in_flight_bound;
    @(posedge clk_i) disable iff (!rst_ni) alloc_count_q <= (PtrW + 1)'(InFlight);
  endproperty
  a_in_flight_bound: assert property (p_in_flight_bound);
`endif

endmodule
