/// Real-time mipmap generator of the TEXRAM (000 §12, Fig. 14): level-0 texels stream in, the
/// 2 x 2 box levels up to 1 x 1 are computed on the fly and every texel of every level leaves
/// as a write of one 8-bit bank cell. Bit-exact with the golden texram::MipgenStream
/// (golden/texram/mipgen_stream.hpp), which defines the input order, the output order and
/// the arithmetic; its values are build_pyramid's and its cells Geometry::cell's.
///
/// Input: one item per level-0 texel in source order: raster order, or interlaced, field 1
/// (lines 0, 2, ...) then field 2 (lines 1, 3, ...). A field-2 item carries in_above_i, the
/// level-0 texel above it (the chip reads that line back from its banks into the shift
/// registers 826); elsewhere in_above_i is ignored. A one-line frame is never interlaced.
/// After a frame's last texel the next item starts a new frame, of the format then on cfg_*.
/// in_start_i marks a frame's first texel: the position restarts at (0, 0), so a frame cut
/// short (the video unit drops it) leaves nothing behind; elsewhere in the stream it is 0.
///
/// Output, per input item: its level-0 write(s), then each higher-level texel the item
/// completes, ascending level. A texel of a level less than 2 texels wide (high) is written
/// to each of its replica cells, row-major in stored coordinates. One write per clock.
///
/// Datapath, one texel at a time (the texel being written, lvl_q/x_q/y_q, its 8-bit value val_q
/// and its carried value car_q): with its last write the texel enters the stage of its level,
/// which either keeps a partial sum or completes a texel of the next level; that texel is then
/// written the same way, and so on. Stage l (level l in, level l + 1 out) has
///   - a hold register: 1404, an even column's carried value waiting for its odd neighbour
///     (interlaced level 0: FIFO 1408 as a one-entry register holding texel + above);
///   - a line FIFO (tmu_mip_line_fifo) of 2^(MaxLog2-1-l) pair sums, half a line of level l
///     (FIFO 1408 as a line buffer): the even line's pair sums wait for the odd line below.
/// The rounding rule is golden/texram/mipmap.hpp's: level l's carried values have
/// K(l) = min(2 l, CarryBits) fraction bits (stage l's registers ChW + 1 + K(l) bits), sums are
/// exact, the next level's texel is the box sum rounded half up once, (sum + 2^(K+1)) >> (K+2),
/// and its carried value the sum rounded to K(l + 1) fraction bits. The default CarryBits keeps
/// every sum exact (every level within 0.5 of level 0's box mean); CarryBits = 0 rounds every
/// level. A one-texel-wide (-high) level repeats its column (row): the pair is twice the texel.
///
/// Timing: an input is accepted while the generator is idle, or in the cycle its last
/// pending write leaves (so in_ready_o depends on wr_ready_i); a texel's writes leave one per
/// clock; completing a texel of the next level costs no extra cycle. So an item takes as
/// many cycles as it makes writes: one for most items, 4/3 on average for a square texture
/// (more for the replicas of one-texel-wide levels), the frame's last item one per level.
///
/// Configuration (cfg_*) is quasi-static: change it only between frames, while idle (the
/// source position is then back at (0, 0), and every partial sum completes within its frame).
///
/// Example: 2 x 2 texels a b / c d, not interlaced, one plane. a: write (level 0, x 0, y 0),
/// a waits in hold_q[0]; b: write (0, 1, 0), the pair a + b waits in the level-0 line FIFO;
/// c: write (0, 0, 1), c waits in hold_q[0]; d: write (0, 1, 1), then c + d plus the FIFO's
/// a + b is the box sum and the level-1 texel (a + b + c + d + 2) >> 2 goes to its four
/// replica cells (1, 0, 0), (1, 1, 0), (1, 0, 1), (1, 1, 1): 8 writes in 8 cycles.
module tmu_mipgen #(
  /// Largest texture side 2^MaxLog2 the line FIFOs are sized for (1..MaxMipLog2).
  parameter int unsigned MaxLog2 = tmu_pkg::MaxMipLog2,
  /// Fraction bits the levels' carried values keep at most (0..2 MaxMipLog2; mipmap.hpp's
  /// carry): 2 MaxMipLog2 keeps every sum exact, 0 rounds every level.
  parameter int unsigned CarryBits = 2 * tmu_pkg::MaxMipLog2
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  /// Frame format: log2 of the level-0 width and height (0..MaxLog2), interlaced source.
  input  tmu_pkg::mip_log2_t   cfg_log2_w_i,
  input  tmu_pkg::mip_log2_t   cfg_log2_h_i,
  input  logic                 cfg_interlaced_i,
  /// Addresses: the texture has four byte planes (else one); the plane this stream fills.
  input  logic                 cfg_four_planes_i,
  input  tmu_pkg::byte_plane_t cfg_plane_i,

  /// Level-0 texels in source order; in_above_i: the texel above (interlaced field 2).
  input  logic                 in_valid_i,
  output logic                 in_ready_o,
  input  tmu_pkg::channel_t    in_texel_i,
  input  tmu_pkg::channel_t    in_above_i,
  input  logic                 in_start_i,

  /// Cell writes: texel (wr_x_o, wr_y_o) (stored coordinates) of level wr_level_o, and its
  /// bank and address (tmu_bank_address).
  output logic                 wr_valid_o,
  input  logic                 wr_ready_i,
  output tmu_pkg::mip_level_t  wr_level_o,
  output tmu_pkg::mip_coord_t  wr_x_o,
  output tmu_pkg::mip_coord_t  wr_y_o,
  output tmu_pkg::channel_t    wr_value_o,
  output tmu_pkg::bank_t       wr_bank_o,
  output tmu_pkg::bank_addr_t  wr_addr_o
);

  localparam int unsigned ChW    = tmu_pkg::ChannelW;
  localparam int unsigned Stages = MaxLog2;  // stage l: level l in, level l + 1 out
  // Fraction bits of the values entering the last stage, the most any stage holds.
  localparam int unsigned KMax   = (2 * (Stages - 1) < CarryBits) ? 2 * (Stages - 1) : CarryBits;
  localparam int unsigned CarW   = ChW + KMax;      // a carried value
  localparam int unsigned PairW  = ChW + 1 + KMax;  // a sum of two
  localparam int unsigned SumW   = ChW + 2 + KMax;  // a box sum
  localparam int unsigned KW     = $clog2(2 * tmu_pkg::MaxMipLog2 + 3);  // 0 .. K + 2
  localparam int unsigned CoordW = tmu_pkg::MipCoordW;
  localparam int unsigned LevelW = tmu_pkg::MipLevelW;
  localparam int unsigned StageW = (Stages > 1) ? $clog2(Stages) : 1;

  if (MaxLog2 < 1 || MaxLog2 > tmu_pkg::MaxMipLog2 || CoordW < MaxLog2 ||
      (1 << LevelW) <= MaxLog2) begin : gen_check
    $error("tmu_mipgen: MaxLog2 must be 1..MaxMipLog2");
  end
  if (CarryBits > 2 * tmu_pkg::MaxMipLog2) begin : gen_check_carry
    $error("tmu_mipgen: CarryBits must be 0..2 MaxMipLog2");
  end

  // ---- Source position: the level-0 texel of the next input item ------------------------------

  logic [CoordW:0]     width, height;  // 2^log2
  logic                interlaced;     // fields in effect: interlaced and more than one line
  tmu_pkg::mip_coord_t src_x_q, src_x_d, src_y_q, src_y_d;
  logic [CoordW:0]     src_y_step;

  // The item's place: a frame's first texel restarts at (0, 0) (after a frame cut short).
  tmu_pkg::mip_coord_t pos_x, pos_y;
  assign pos_x = in_start_i ? '0 : src_x_q;
  assign pos_y = in_start_i ? '0 : src_y_q;

  assign width      = (CoordW + 1)'(1) << cfg_log2_w_i;
  assign height     = (CoordW + 1)'(1) << cfg_log2_h_i;
  assign interlaced = cfg_interlaced_i && cfg_log2_h_i != '0;

  // ---- The texel being written ---------------------------------------------------------------

  logic                busy_q, busy_d;
  tmu_pkg::mip_level_t lvl_q, lvl_d;
  tmu_pkg::mip_coord_t x_q, x_d, y_q, y_d;  // coordinates within its level
  tmu_pkg::channel_t   val_q, val_d;
  logic [CarW-1:0]     car_q, car_d;        // its carried value, K(lvl_q) fraction bits
  tmu_pkg::channel_t   above_q, above_d;    // level 0, interlaced field 2: the texel above
  logic [1:0]          rep_q, rep_d;        // replica being written: {y, x}

  logic wide, high, top;  // the texel's level is >= 2 wide, >= 2 high, the 1 x 1 top
  logic rep_last;         // the texel's last write

  assign wide     = cfg_log2_w_i > lvl_q;
  assign high     = cfg_log2_h_i > lvl_q;
  assign top      = !wide && !high;
  assign rep_last = (wide || rep_q[0]) && (high || rep_q[1]);

  // ---- Stage of the texel's level: partial sums, and the next level's texel ------------------

  logic [Stages*PairW-1:0] hold_rdata;   // each stage's register 1404, zero-extended
  logic [Stages*PairW-1:0] line_rdata;   // each stage's line FIFO at column pair x_q >> 1, too
  logic [StageW-1:0]       stage;
  logic [PairW-1:0]        hold_rd, line_rd, hold_wd, pair;
  logic [SumW-1:0]         sum;
  logic                    hold_we, line_we, produce;

  assign stage   = top ? '0 : StageW'(lvl_q);  // a level below the top has a stage
  assign hold_rd = hold_rdata[stage*PairW +: PairW];
  assign line_rd = line_rdata[stage*PairW +: PairW];

  always_comb begin
    pair    = '0;
    hold_wd = '0;
    sum     = '0;
    hold_we = 1'b0;
    line_we = 1'b0;
    produce = 1'b0;
    if (!top) begin
      if (interlaced && lvl_q == '0) begin
        // Fig. 14(a), interlaced: field 2 adds the texel above (adder 1402); an even column
        // waits in FIFO 1408 (one entry), the odd one completes the level-1 texel (1410).
        pair = PairW'(val_q) + PairW'(above_q);
        if (y_q[0]) begin
          if (!wide) begin
            produce = 1'b1;
            sum     = {pair, 1'b0};
          end else if (!x_q[0]) begin
            hold_we = 1'b1;
            hold_wd = pair;
          end else begin
            produce = 1'b1;
            sum     = SumW'(hold_rd) + SumW'(pair);
          end
        end
      end else begin
        // Columns pair first (register 1404, adder 1402), then lines (line FIFO 1408, 1410).
        if (wide && !x_q[0]) begin
          hold_we = 1'b1;
          hold_wd = PairW'(car_q);
        end else begin
          pair = wide ? PairW'(hold_rd[CarW-1:0]) + PairW'(car_q) : {1'b0, car_q} << 1;
          if (!high) begin
            produce = 1'b1;
            sum     = {pair, 1'b0};
          end else if (!y_q[0]) begin
            line_we = 1'b1;
          end else begin
            produce = 1'b1;
            sum     = SumW'(line_rd) + SumW'(pair);
          end
        end
      end
    end
  end

  // The rounding rule: the level's fraction bits k, the next level's k_next; the texel is the
  // sum plus half of 2^(k+2) with k + 2 bits dropped, the carried value the sum with
  // k + 2 - k_next (0..2) bits dropped, rounded half up the same way.
  logic [KW-1:0]   k, k_next, drop_bits;
  logic [SumW-1:0] texel_sum, carry_sum;

  // K(l) = min(2 l, CarryBits) of every level, a table fixed at elaboration.
  localparam int unsigned Levels = 1 << LevelW;
  logic [Levels*KW-1:0] frac_of;
  for (genvar l = 0; l < Levels; l++) begin : gen_frac
    assign frac_of[l*KW +: KW] = KW'((2 * l < CarryBits) ? 2 * l : CarryBits);
  end
  tmu_pkg::mip_level_t lvl_next;
  assign lvl_next = lvl_q + LevelW'(1);  // lvl_q <= MaxLog2 < 15: no wrap
  assign k         = frac_of[lvl_q*KW +: KW];
  assign k_next    = frac_of[lvl_next*KW +: KW];
  assign drop_bits = k + KW'(2) - k_next;
  // At most 255 2^(k+2) + 2^(k+1) < 2^SumW: no carry out.
  assign texel_sum = (sum + (SumW'(2) << k)) >> (k + KW'(2));
  assign carry_sum = (drop_bits == '0) ? sum
                   : (sum + (SumW'(1) << (drop_bits - KW'(1)))) >> drop_bits;
  // The texel fits 8 bits and the carried value CarW bits (a level Stages top's does not, and
  // is never read).
  logic unused_sum_bits;
  assign unused_sum_bits = ^{texel_sum[SumW-1:ChW], carry_sum[SumW-1:CarW]};

  // ---- Control ---------------------------------------------------------------------------------

  logic wr_fire, done, in_fire;

  assign wr_fire    = busy_q && wr_ready_i;
  assign done       = wr_fire && rep_last;  // the texel enters its stage
  assign in_ready_o = !busy_q || (done && !produce);
  assign in_fire    = in_valid_i && in_ready_o;

  always_comb begin
    busy_d     = busy_q;
    lvl_d      = lvl_q;
    x_d        = x_q;
    y_d        = y_q;
    val_d      = val_q;
    car_d      = car_q;
    above_d    = above_q;
    rep_d      = rep_q;
    src_x_d    = src_x_q;
    src_y_d    = src_y_q;
    src_y_step = '0;

    if (wr_fire && !rep_last) begin  // next replica, row-major
      rep_d = (!wide && !rep_q[0]) ? {rep_q[1], 1'b1} : 2'b10;
    end
    if (done) begin
      if (produce) begin  // the next level's texel, written next
        lvl_d = lvl_q + LevelW'(1);
        x_d   = x_q >> 1;
        y_d   = y_q >> 1;
        val_d = texel_sum[ChW-1:0];
        // Level Stages is a top: its carried value, which may not fit, is never read.
        car_d = carry_sum[CarW-1:0];
        rep_d = '0;
      end else begin
        busy_d = 1'b0;
      end
    end
    if (in_fire) begin
      busy_d  = 1'b1;
      lvl_d   = '0;
      x_d     = pos_x;
      y_d     = pos_y;
      val_d   = in_texel_i;
      car_d   = CarW'(in_texel_i);
      above_d = in_above_i;
      rep_d   = '0;
      // Source order: along the line; then the next line, or of the same field; a field's
      // end goes to field 2 (line 1), a frame's end to line 0.
      if ((CoordW + 1)'(pos_x) + (CoordW + 1)'(1) == width) begin
        src_x_d    = '0;
        src_y_step = (CoordW + 1)'(pos_y) + (interlaced ? (CoordW + 1)'(2) : (CoordW + 1)'(1));
        if (src_y_step >= height) begin
          src_y_d = (interlaced && !pos_y[0]) ? CoordW'(1) : '0;
        end else begin
          src_y_d = src_y_step[CoordW-1:0];
        end
      end else begin
        src_x_d = pos_x + CoordW'(1);
        src_y_d = pos_y;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q  <= 1'b0;
      src_x_q <= '0;
      src_y_q <= '0;
    end else begin
      busy_q  <= busy_d;
      src_x_q <= src_x_d;
      src_y_q <= src_y_d;
    end
  end

  // The texel's data: only observed while busy_q, no reset.
  always_ff @(posedge clk_i) begin
    lvl_q   <= lvl_d;
    x_q     <= x_d;
    y_q     <= y_d;
    val_q   <= val_d;
    car_q   <= car_d;
    above_q <= above_d;
    rep_q   <= rep_d;
  end

  for (genvar l = 0; l < Stages; l++) begin : gen_stage
    localparam int unsigned Depth = 1 << (MaxLog2 - 1 - l);  // half a line of level l
    localparam int unsigned FifoAddrW = (Depth > 1) ? $clog2(Depth) : 1;
    // A pair of level l's carried values (level 0 interlaced: texel + above, 9 bits).
    localparam int unsigned W = ChW + 1 + ((2 * l < CarryBits) ? 2 * l : CarryBits);
    logic [W-1:0] line_entry;
    logic [W-1:0] hold_q;

    // Register 1404: no reset, every frame writes an even column before its odd one reads it.
    always_ff @(posedge clk_i) begin
      if (done && hold_we && stage == StageW'(l)) hold_q <= hold_wd[W-1:0];
    end
    assign hold_rdata[l*PairW +: PairW] = PairW'(hold_q);

    tmu_mip_line_fifo #(
      .Depth (Depth),
      .Width (W)
    ) u_line_fifo (
      .clk_i   (clk_i),
      .we_i    (done && line_we && stage == StageW'(l)),
      .addr_i  (x_q[FifoAddrW:1]),
      .wdata_i (pair[W-1:0]),
      .rdata_o (line_entry)
    );
    assign line_rdata[l*PairW +: PairW] = PairW'(line_entry);
  end

  // ---- Writes --------------------------------------------------------------------------------

  assign wr_valid_o = busy_q;
  assign wr_level_o = lvl_q;
  assign wr_x_o     = wide ? x_q : CoordW'(rep_q[0]);
  assign wr_y_o     = high ? y_q : CoordW'(rep_q[1]);
  assign wr_value_o = val_q;

  tmu_bank_address #(
    .MaxLog2 (MaxLog2)
  ) u_bank_address (
    .cfg_log2_w_i      (cfg_log2_w_i),
    .cfg_log2_h_i      (cfg_log2_h_i),
    .cfg_four_planes_i (cfg_four_planes_i),
    .cfg_block_grid_i  (1'b0),
    .in_level_i        (lvl_q),
    .in_x_i            (wr_x_o),
    .in_y_i            (wr_y_o),
    .in_plane_i        (cfg_plane_i),
    .out_bank_o        (wr_bank_o),
    .out_addr_o        (wr_addr_o)
  );

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // The format fits the FIFOs, and no texel climbs above the top level.
  a_cfg_in_range: assert property (@(posedge clk_i) disable iff (!rst_ni)
      32'(cfg_log2_w_i) <= MaxLog2 && 32'(cfg_log2_h_i) <= MaxLog2);
  a_level_in_range: assert property (@(posedge clk_i) disable iff (!rst_ni)
      busy_q |-> (lvl_q <= cfg_log2_w_i || lvl_q <= cfg_log2_h_i));
`endif

endmodule
