/// The TEXRAM's video unit (000 §11-12, Fig. 8 808, Fig. 14; docs/video.md): the serial video
/// port, a mipmap generator per byte plane, the page-row buffers and their arbiter into the
/// shared memory, the reads of the line above into the shift registers 826, and double
/// buffering by a swap of the front buffer. Bit-exact, access for access, with the golden
/// texram::video::VideoMap (golden/texram/video/video_map.hpp) with external_reads: the data of
/// the reads come back on mem_resp. It joins tmu_video_port (VideoReceiver), four tmu_mipgen
/// (MipgenStream, plane p) and tmu_video_rows (RowBuffers, segment_cells = Cells).
///
/// Items, one at a time (in before cycle when both are offered; the next only when the unit is
/// back in StIdle, so only the order of their effects matters, not the clocks they take):
///   in     one item of the port (VideoMap::receive). Through tmu_video_port; its output r:
///          the frame under way dropped: a flush of its tag to the rows; not accepted: done;
///          a frame's first texel begins a frame (tag + 1, the buffer not holding the newest
///          complete frame, the mipgens restarted); an interlaced frame higher than 2 lines
///          requests, at x = 0, the reads of the line above a line ahead (line 0 at line
///          height - 2, line y + 1 at field-2 line y; a field-2 line whose reads are not all
///          done is counted, late_reads); each plane's texel byte, with the line store's
///          byte of the texel above, goes to its mipgen, and every write it makes to the rows
///          as a put (plane 0's writes first); the frame's last texel flushes the frame and
///          holds it in the rows until its swap, or, while a swap is pending, is an overrun
///          (not shown, the next frame to the same buffer).
///   cycle  one memory cycle (VideoMap::cycle): a cycle item to the rows; its access also goes
///          out on mem_req (a write with its cells; a read, whose cells come back on mem_resp
///          and, where a row buffer still holds the cell, are taken from the rows' mask and
///          data, into the line store); the pending frame, once the rows say no buffer of it
///          is left (drained), becomes the front buffer (swap) and the barrier is lifted (a
///          hold of tag 0xFFFF). The out item follows.
///
/// States (StIdle takes items; the rest carry one item's effects out in golden's order):
///   StClear    after reset or a new format or base: the line store to 0, one word a clock;
///              in its first clock a cycle item the sampler takes closes the rows' pages
///   StIdle     takes an in item (to StItem) or a cycle item (to StAccess)
///   StItem     the port's output r; r.dropped: the flush of the frame under way
///   StLine     begins the reads of the line above: counts a late line, the first row
///   StReads    one read item a clock: each row the line's cells touch, in bank 0 and 1, in
///              the order golden's walk of the line first touches them (at first_row)
///   StFeed     the texel bytes to the mipgens (and a two-line frame's line 0 to the store)
///   StDrain    mipgen p's writes to the rows as puts, p = 0, 1, ...
///   StEnd      the frame's last texel: its flush
///   StHold     ... and the barrier on it (when no swap is pending)
///   StDone     releases the port's output
///   StAccess   the rows' output: the request of its first word on mem_req, the swap decision
///   StBeat     the request of a further word of the row (rows of more than 8 cells)
///   StResp     a read waits for its word's response (one per request, in order, latency >= 1)
///   StCapture  the word's cells into the line store, one a clock; then the next word's read
///   StUnhold   after a swap: the barrier lifted (hold 0xFFFF)
///   StShow     the out item, until taken
///
/// The line store (the shift registers 826) holds two lines, line a in slot (a >> 1) & 1, so
/// the line being read never overwrites the line in use; each slot two column parities, each
/// planes * (stored_width / 2) cells. It is four byte-plane RAMs of words {slot, x & 1, x >> 1}
/// (golden's cell planes * (x >> 1) + p is plane p of word x >> 1), read through a register
/// and written through one port: a captured cell, a two-line frame's texel of line 0 as it
/// arrives, or a word of the clearing sweep. A read is remembered in a FIFO beside the rows'
/// read queue (its line and buffer), so that its capture knows which cells are its line's.
///
/// Configuration: quasi-static, written between runs while the unit is quiet (no frame under
/// way, no swap pending, the rows idle). A format or base that differs from the registered copy
/// starts the unit afresh as golden builds a new VideoMap (golden VideoUnit::configure): tag 0,
/// front 0, nothing pending, the line store cleared, and every bank's page closed, as a new
/// RowBuffers has them: a cycle item to the rows that the sampler wants and, the rows being
/// drained, gets (its output dropped). The rows' buffers are empty then and their counters, like
/// the port's, run on. max_wait and read_wait go straight to the rows.
///
/// Tags are 16 bits (VideoTag): frames 1 .. 0xFFFE, then 1 again; 0xFFFF means no frame held.
/// The rows compare them as serial numbers, so a video runs for ever.
///
/// Example: a 2 x 4 interlaced one-plane video, base1 = 512, after reset: frame 1 goes to
/// buffer 1. Item (0, 2), field 1's last line, requests line 0's reads: one cell a bank at 512,
/// so (bank 0, 512) and (bank 1, 512). Item (0, 1) starts field 2: if no cycle item has
/// accessed those reads yet, late_reads counts it; it requests line 2's reads (cell 513, the
/// same two rows). The cycle item that starts the read of (bank 0, 512) sends mem_req {read,
/// bank 0, 512} and waits for the response; its cell 0 (line 0, x 0) comes from the row buffer
/// still collecting frame 1 (the rows' mask), cell 1 is line 2's (its own read takes it), the
/// others no line's. The last item (1, 3) flushes frame 1 and holds it; the cycle after which
/// no buffer of frame 1 is left swaps: out swap 1, front 1.
module tmu_video_unit #(
  /// Cells of a row buffer (tmu_video_rows' Cells): 8 (the co-simulated block) to 512 (a page,
  /// the chip's rows). The memory port carries 8 cells a clock, so a row's access goes out as
  /// Cells / 8 requests of consecutive words (see mem_req).
  parameter int unsigned Cells     = 8,
  /// Row buffers of each bank.
  parameter int unsigned Buffers   = 8,
  /// Entries of the rows' read queue and of this unit's FIFO of line reads.
  parameter int unsigned ReadDepth = 64,
  /// Largest side 2^MaxLog2 (the mipgens' line FIFOs, the line store), 1..MaxMipLog2.
  parameter int unsigned MaxLog2   = 9
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,

  /// Format (log2 of the level-0 width and height, interlaced, four planes else one), the two
  /// buffers' first cells in every bank, the arbiter's bounds L and read_wait.
  input  tmu_pkg::mip_log2_t    cfg_log2_w_i,
  input  tmu_pkg::mip_log2_t    cfg_log2_h_i,
  input  logic                  cfg_interlaced_i,
  input  logic                  cfg_four_planes_i,
  input  tmu_pkg::bank_addr_t   cfg_base0_i,
  input  tmu_pkg::bank_addr_t   cfg_base1_i,
  input  tmu_pkg::video_tag_t   cfg_max_wait_i,
  input  tmu_pkg::video_tag_t   cfg_read_wait_i,

  /// The serial video port: an item's flags and texel.
  input  logic                  in_valid_i,
  output logic                  in_ready_o,
  input  tmu_pkg::video_flags_t in_flags_i,
  input  tmu_pkg::video_texel_t in_texel_i,

  /// Memory cycles; the sampler wants the cycle.
  input  logic                  cycle_valid_i,
  output logic                  cycle_ready_o,
  input  logic                  cycle_sampler_i,

  /// Per cycle item: the sampler got it, a write or read started (its page fault, its wait),
  /// a swap at its end, the front buffer after it.
  output logic                  out_valid_o,
  input  logic                  out_ready_i,
  output logic                  out_granted_o,
  output logic                  out_write_o,
  output logic                  out_read_o,
  output logic                  out_fault_o,
  output tmu_pkg::video_tag_t   out_wait_o,
  output logic                  out_swap_o,
  output logic                  out_front_o,

  /// The access of a cycle item (the memory takes every request): Cells / 8 requests, one a
  /// clock, of the row's words in order, each 8 cells at addr, addr + 8, ...: a write of the
  /// word's masked cells, or a read of the word (mask and data 0), whose response comes before
  /// the next word's read goes.
  output logic                  mem_req_valid_o,
  output logic                  mem_req_write_o,
  output tmu_pkg::bank_t        mem_req_bank_o,
  output tmu_pkg::bank_addr_t   mem_req_addr_o,
  output logic [7:0]            mem_req_mask_o,
  output logic [63:0]           mem_req_data_o,

  /// A read's word, cell i in bits [8i+7:8i].
  input  logic                  mem_resp_valid_i,
  input  logic [63:0]           mem_resp_data_i,

  /// Counters (32 bits, wrapping).
  output tmu_pkg::stat_count_t  stat_frames_shown_o,
  output tmu_pkg::stat_count_t  stat_frames_dropped_o,
  output tmu_pkg::stat_count_t  stat_overruns_o,
  output tmu_pkg::stat_count_t  stat_late_reads_o,
  output tmu_pkg::stat_count_t  stat_lost_writes_o,
  output tmu_pkg::stat_count_t  stat_forced_o
);

  localparam int unsigned Planes   = tmu_pkg::Planes;
  localparam int unsigned PlaneW   = tmu_pkg::BytePlaneW;
  localparam int unsigned ChW      = tmu_pkg::ChannelW;
  localparam int unsigned BankW    = tmu_pkg::BankW;
  localparam int unsigned AddrW    = tmu_pkg::BankAddrW;
  localparam int unsigned CoordW   = tmu_pkg::MipCoordW;
  localparam int unsigned TagW     = tmu_pkg::VideoTagW;
  localparam int unsigned StatW    = tmu_pkg::StatCountW;
  localparam int unsigned CellBits = $clog2(Cells);
  localparam int unsigned SegW     = AddrW - CellBits;
  // The line store: a word per column pair x >> 1 of a slot and parity, a byte per plane.
  localparam int unsigned ColW     = (MaxLog2 > 1) ? MaxLog2 - 1 : 1;
  localparam int unsigned StoreAW  = ColW + 2;
  localparam int unsigned Words    = 1 << StoreAW;
  localparam int unsigned PtrW     = (ReadDepth > 1) ? $clog2(ReadDepth) : 1;
  localparam int unsigned CountW   = $clog2(ReadDepth + 1);
  localparam int unsigned CfgW     = 2 * tmu_pkg::MipLog2W + 2 + 2 * AddrW;
  localparam int unsigned NLog2W   = 4;  // log2 of a line's cells in a bank, up to 9 + 2

  // A row's words on the memory port.
  localparam int unsigned Beats    = Cells / 8;
  localparam int unsigned BeatW    = (Beats > 1) ? $clog2(Beats) : 1;

  if (Cells < 8 || Cells > (1 << tmu_pkg::PageLog2) || (Cells & (Cells - 1)) != 0) begin : gen_check
    $error("tmu_video_unit: Cells must be a power of two, 8..512 (the memory ports carry 8 cells)");
  end

  typedef enum logic [3:0] {
    StClear,
    StIdle,
    StItem,
    StLine,
    StReads,
    StFeed,
    StDrain,
    StEnd,
    StHold,
    StDone,
    StAccess,
    StBeat,
    StResp,
    StCapture,
    StUnhold,
    StShow
  } state_e;

  // ---- Registers -------------------------------------------------------------------------------

  state_e               state_q, state_d;
  logic [StoreAW-1:0]   clr_q, clr_d;        // the clearing sweep's word (0 outside StClear)
  logic [CfgW-1:0]      cfg_q;               // format and bases the unit started with
  tmu_pkg::video_tag_t  tag_q, tag_d;        // the frame under way (0: none since the start)
  logic                 cur_q, cur_d;        // its buffer
  logic                 newest_q, newest_d;  // buffer of the newest complete frame
  logic                 pending_q, pending_d;  // that frame waits for its swap
  logic                 front_q, front_d;
  logic                 swap_q, swap_d;      // the cycle item's swap (StAccess on)
  // StReads: the row s_q of bank rb_q being requested, in the group of rows from lo_q.
  // StDrain: the plane. StCapture: the cell.
  logic [SegW-1:0]      s_q, s_d, lo_q, lo_d;
  logic                 rb_q, rb_d;
  logic [1:0]           plane_q, plane_d;
  logic [CellBits-1:0]  cap_q, cap_d;
  logic [BeatW-1:0]     beat_q, beat_d;      // StBeat: the word of the row on mem_req
  logic [63:0]          resp_q;              // a read's response: a word
  tmu_pkg::stat_count_t shown_q, shown_d, overruns_q, overruns_d, late_q, late_d;

  // The FIFO of line reads, parallel to the rows' read queue: each read's line and buffer.
  tmu_pkg::mip_coord_t  rf_line_q [ReadDepth];
  logic                 rf_buf_q  [ReadDepth];
  logic [PtrW-1:0]      rf_head_q, rf_head_d, rf_tail_q, rf_tail_d;
  logic [CountW-1:0]    rf_n_q, rf_n_d;

  // ---- The format -------------------------------------------------------------------------------

  logic [CfgW-1:0]     cfg;
  logic                restart;  // between items, a new format or base: start afresh
  logic [CoordW:0]     height;
  logic                fields;   // interlaced order in effect: interlaced, more than one line
  logic [NLog2W-1:0]   n_log2;   // n = planes * stored_width / 2, a line's cells in a bank
  logic [1:0]          last_plane;

  assign cfg        = {cfg_log2_w_i, cfg_log2_h_i, cfg_interlaced_i, cfg_four_planes_i,
                       cfg_base0_i, cfg_base1_i};
  assign restart    = state_q == StIdle && cfg != cfg_q;
  assign height     = (CoordW + 1)'(1) << cfg_log2_h_i;
  assign fields     = cfg_interlaced_i && cfg_log2_h_i != '0;
  assign n_log2     = ((cfg_log2_w_i == '0) ? '0 : NLog2W'(cfg_log2_w_i - 4'd1)) +
                      (cfg_four_planes_i ? NLog2W'(2) : NLog2W'(0));
  assign last_plane = cfg_four_planes_i ? 2'd3 : 2'd0;

  // ---- The port -----------------------------------------------------------------------------

  logic                  idle;  // an item may be taken
  logic                  port_in_valid, port_in_ready, port_out_valid, port_out_ready;
  logic                  r_accepted, r_frame_start, r_frame_end, r_dropped;
  tmu_pkg::mip_coord_t   r_x, r_y;
  tmu_pkg::video_texel_t r_texel;
  tmu_pkg::stat_count_t  port_dropped;
  // verilator lint_off UNUSEDSIGNAL
  tmu_pkg::video_error_t r_error;
  tmu_pkg::stat_count_t  port_items, port_complete, port_discarded, port_order;
  // verilator lint_on UNUSEDSIGNAL

  assign idle           = state_q == StIdle && !restart;
  assign port_in_valid  = in_valid_i && idle;
  assign in_ready_o     = idle && port_in_ready;
  // The port's output is the item's register: held until its effects are done.
  assign port_out_ready = state_q == StDone;

  tmu_video_port u_port (
    .clk_i,
    .rst_ni,
    .cfg_log2_w_i,
    .cfg_log2_h_i,
    .cfg_interlaced_i,
    .cfg_four_planes_i,
    .in_valid_i                (port_in_valid),
    .in_ready_o                (port_in_ready),
    .in_flags_i,
    .in_texel_i,
    .out_valid_o               (port_out_valid),
    .out_ready_i               (port_out_ready),
    .out_accepted_o            (r_accepted),
    .out_x_o                   (r_x),
    .out_y_o                   (r_y),
    .out_frame_start_o         (r_frame_start),
    .out_frame_end_o           (r_frame_end),
    .out_dropped_o             (r_dropped),
    .out_error_o               (r_error),
    .out_texel_o               (r_texel),
    .stat_items_o              (port_items),
    .stat_frames_complete_o    (port_complete),
    .stat_frames_dropped_o     (port_dropped),
    .stat_items_discarded_o    (port_discarded),
    .stat_field_order_errors_o (port_order)
  );

  // ---- The reads of the line above -----------------------------------------------------------

  logic                reads_at;    // the item begins a line that requests or checks reads
  logic                need_reads;  // ... it requests the reads of read_line
  logic                late;        // ... a field-2 line whose line above is not all read
  tmu_pkg::mip_coord_t read_line;
  logic                capturing;
  tmu_pkg::mip_coord_t line_a;      // the line of `first`: the item's read_line, or the
  logic                line_buf;    // captured read's (the FIFO's head), and its buffer
  tmu_pkg::bank_addr_t first;       // line_a's first cell in its banks
  logic [SegW-1:0]     first_row;
  logic                straddles;   // the line's first texel's planes straddle two rows
  logic [SegW-1:0]     group_hi;    // StReads: the last row of s_q's group
  tmu_pkg::bank_addr_t last_cell;
  logic                last_row;    // StReads: s_q is the row of line_a's last cell

  assign reads_at   = fields && cfg_log2_h_i > 4'd1 && r_x == '0;
  assign need_reads = reads_at && ((CoordW + 1)'(r_y) == height - (CoordW + 1)'(2) ||
                                   (r_y[0] && (CoordW + 1)'(r_y) + (CoordW + 1)'(2) < height));
  assign late       = reads_at && r_y[0] && rf_n_q != '0;
  assign read_line  = r_y[0] ? r_y + CoordW'(1) : '0;
  assign capturing  = state_q == StCapture;
  assign line_a     = capturing ? rf_line_q[rf_head_q] : read_line;
  assign line_buf   = capturing ? rf_buf_q[rf_head_q] : cur_q;
  assign first      = (line_buf ? cfg_base1_i : cfg_base0_i) + ((AddrW'(line_a) >> 1) << n_log2);
  assign last_cell  = first + (AddrW'(1) << n_log2) - AddrW'(1);
  assign last_row   = {s_q, {CellBits{1'b1}}} >= last_cell;
  // Golden requests the rows in the order the line's cells first touch them, texel by texel,
  // plane by plane: texel 2c in bank 0 and texel 2c + 1 in bank 1 take the same cells. So the
  // rows go in groups, bank 0's rows of a group then bank 1's: the first texel's (its row, and
  // the next when its four planes straddle a row end), then each further row alone.
  assign first_row  = first[AddrW-1:CellBits];
  assign straddles  = cfg_four_planes_i && first[CellBits-1:0] > CellBits'(Cells - Planes);
  assign group_hi   = lo_q + SegW'(lo_q == first_row && straddles);

  // ---- The mipgens and the line store ---------------------------------------------------------

  logic [Planes-1:0]   mg_fed;  // the planes of the format
  logic [Planes-1:0]   mg_in_valid;
  logic [Planes-1:0]   mg_in_ready, mg_wr_valid, mg_wr_ready;
  // Plane p's fields at [p W +: W] (Yosys 0.23 takes one packed dimension).
  logic [Planes*BankW-1:0]  mg_wr_bank;
  logic [Planes*AddrW-1:0]  mg_wr_addr;
  logic [Planes*ChW-1:0]    mg_wr_value;

  // The store's one write port (a byte per plane) and read address; a plane's read register.
  logic [Planes-1:0]   st_we;
  logic [StoreAW-1:0]  st_waddr, st_raddr;
  logic [Planes*ChW-1:0]    st_wdata;
  logic [Planes*ChW-1:0]    above;
  logic                above_slot;

  assign mg_fed      = cfg_four_planes_i ? 4'b1111 : 4'b0001;
  assign mg_in_valid = (state_q == StFeed) ? mg_fed : '0;
  // The texel above the item's, of line y - 1 (for line 0 a word the mipgen ignores): slot
  // ((y - 1) >> 1) & 1, bit 1 of y flipped by the borrow of an even y.
  assign above_slot = r_y[1] ^ !r_y[0];
  assign st_raddr   = {above_slot, r_x[0], r_x[ColW:1]};

  for (genvar p = 0; p < Planes; p++) begin : gen_plane
    // Plane p of the line store: written before it is read (StClear after reset).
    tmu_pkg::channel_t lane_q [Words];
    tmu_pkg::channel_t rdata_q;

    always_ff @(posedge clk_i) begin
      if (st_we[p]) lane_q[st_waddr] <= st_wdata[p*ChW +: ChW];
      rdata_q <= lane_q[st_raddr];
    end
    assign above[p*ChW +: ChW] = rdata_q;

    // verilator lint_off UNUSEDSIGNAL
    tmu_pkg::mip_level_t wr_level;
    tmu_pkg::mip_coord_t wr_x, wr_y;
    // verilator lint_on UNUSEDSIGNAL

    tmu_mipgen #(
      .MaxLog2 (MaxLog2)
    ) u_mipgen (
      .clk_i,
      .rst_ni,
      .cfg_log2_w_i,
      .cfg_log2_h_i,
      .cfg_interlaced_i,
      .cfg_four_planes_i,
      .cfg_plane_i       (PlaneW'(p)),
      .in_valid_i        (mg_in_valid[p]),
      .in_ready_o        (mg_in_ready[p]),
      .in_texel_i        (r_texel[(Planes-1-p)*ChW +: ChW]),
      .in_above_i        (above[p*ChW +: ChW]),
      .in_start_i        (r_frame_start),
      .wr_valid_o        (mg_wr_valid[p]),
      .wr_ready_i        (mg_wr_ready[p]),
      .wr_level_o        (wr_level),
      .wr_x_o            (wr_x),
      .wr_y_o            (wr_y),
      .wr_value_o        (mg_wr_value[p*ChW +: ChW]),
      .wr_bank_o         (mg_wr_bank[p*BankW +: BankW]),
      .wr_addr_o         (mg_wr_addr[p*AddrW +: AddrW])
    );
  end

  // ---- The rows ---------------------------------------------------------------------------------

  logic                 put_valid, put_ready, flush_valid, flush_ready, hold_valid, hold_ready;
  logic                 read_valid, read_ready, rows_cycle_valid, rows_cycle_ready;
  logic                 close_pages, rows_sampler;
  tmu_pkg::bank_addr_t  put_addr;
  tmu_pkg::video_tag_t  hold_tag;
  logic                 o_valid, o_ready, o_write, o_read, o_drained;
  tmu_pkg::bank_t       o_bank;
  tmu_pkg::bank_addr_t  o_addr;
  logic [Cells-1:0]     o_mask;
  logic [8*Cells-1:0]   o_data;
  // verilator lint_off UNUSEDSIGNAL
  tmu_pkg::stat_count_t rows_cells_in, rows_max_ready, rows_max_busy;
  // verilator lint_on UNUSEDSIGNAL

  assign put_valid        = state_q == StDrain && mg_wr_valid[plane_q];
  assign put_addr         = (cur_q ? cfg_base1_i : cfg_base0_i) +
                            mg_wr_addr[plane_q*AddrW +: AddrW];
  for (genvar p = 0; p < Planes; p++) begin : gen_wr_ready
    assign mg_wr_ready[p] = state_q == StDrain && plane_q == 2'(p) && put_ready;
  end
  assign flush_valid      = (state_q == StItem && r_dropped) || state_q == StEnd;
  assign hold_valid       = state_q == StHold || state_q == StUnhold;
  assign hold_tag         = (state_q == StUnhold) ? '1 : tag_q;
  assign read_valid       = state_q == StReads;
  // StClear's first clock closes the pages with a sampler's cycle; its output goes next clock.
  assign close_pages      = state_q == StClear && clr_q == '0;
  assign rows_cycle_valid = (cycle_valid_i && idle && !in_valid_i) || close_pages;
  assign rows_sampler     = cycle_sampler_i || close_pages;
  assign cycle_ready_o    = idle && !in_valid_i && rows_cycle_ready;
  // The rows' output is the cycle item's register: held until the out item is taken.
  assign o_ready          = (state_q == StShow && out_ready_i) ||
                            (state_q == StClear && clr_q == StoreAW'(1));

  tmu_video_rows #(
    .Cells     (Cells),
    .Buffers   (Buffers),
    .ReadDepth (ReadDepth)
  ) u_rows (
    .clk_i,
    .rst_ni,
    .cfg_max_wait_i,
    .cfg_read_wait_i,
    .put_valid_i          (put_valid),
    .put_ready_o          (put_ready),
    .put_bank_i           (mg_wr_bank[plane_q*BankW +: BankW]),
    .put_addr_i           (put_addr),
    .put_value_i          (mg_wr_value[plane_q*ChW +: ChW]),
    .put_tag_i            (tag_q),
    .flush_valid_i        (flush_valid),
    .flush_ready_o        (flush_ready),
    .flush_tag_i          (tag_q),
    .hold_valid_i         (hold_valid),
    .hold_ready_o         (hold_ready),
    .hold_tag_i           (hold_tag),
    .read_valid_i         (read_valid),
    .read_ready_o         (read_ready),
    .read_bank_i          ({2'b00, rb_q}),
    .read_addr_i          ({s_q, {CellBits{1'b0}}}),
    .cycle_valid_i        (rows_cycle_valid),
    .cycle_ready_o        (rows_cycle_ready),
    .cycle_sampler_i      (rows_sampler),
    .out_valid_o          (o_valid),
    .out_ready_i          (o_ready),
    .out_granted_o,
    .out_write_o          (o_write),
    .out_read_o           (o_read),
    .out_fault_o,
    .out_bank_o           (o_bank),
    .out_addr_o           (o_addr),
    .out_mask_o           (o_mask),
    .out_data_o           (o_data),
    .out_wait_o,
    .out_drained_o        (o_drained),
    .stat_cells_in_o      (rows_cells_in),
    .stat_lost_writes_o,
    .stat_forced_o,
    .stat_max_ready_o     (rows_max_ready),
    .stat_max_busy_bank_o (rows_max_busy)
  );

  assign out_read_o  = o_read;
  assign out_write_o = o_write;
  assign out_valid_o = state_q == StShow;
  assign out_swap_o  = swap_q;
  assign out_front_o = front_q;

  logic [BeatW-1:0] req_beat;  // the word on mem_req: 0 in StAccess

  assign req_beat        = (state_q == StBeat) ? beat_q : '0;
  assign mem_req_valid_o = (state_q == StAccess && (o_write || o_read)) || state_q == StBeat;
  assign mem_req_write_o = o_write;
  assign mem_req_bank_o  = o_bank;
  assign mem_req_addr_o  = o_addr | (AddrW'(req_beat) << 3);
  // A read's mask and data are the rows' buffered cells, for the capture, not the memory.
  assign mem_req_mask_o  = o_write ? 8'(o_mask >> (8 * req_beat)) : '0;
  assign mem_req_data_o  = o_write ? 64'(o_data >> (64 * req_beat)) : '0;

  // ---- The capture of a read's cell cap_q ------------------------------------------------------

  tmu_pkg::bank_addr_t cap_addr;
  logic [AddrW:0]      cap_rel;      // its place in line_a's cells, negative before them
  logic                cap_in_line;
  logic [1:0]          cap_plane;
  logic [ColW-1:0]     cap_col;
  tmu_pkg::channel_t   cap_value;

  assign cap_addr    = {o_addr[AddrW-1:CellBits], cap_q};
  assign cap_rel     = {1'b0, cap_addr} - {1'b0, first};
  assign cap_in_line = !cap_rel[AddrW] && (cap_rel[AddrW-1:0] >> n_log2) == '0;
  assign cap_plane   = cfg_four_planes_i ? cap_rel[1:0] : 2'd0;
  assign cap_col     = cfg_four_planes_i ? cap_rel[ColW+1:2] : cap_rel[ColW-1:0];
  assign cap_value   = o_mask[cap_q] ? o_data[8*cap_q +: 8] : resp_q[8*cap_q[2:0] +: 8];

  // The store's write port: the sweep, a two-line frame's line 0, a captured cell.
  always_comb begin
    st_we    = '0;
    st_waddr = '0;
    st_wdata = '0;
    unique case (state_q)
      StClear: begin
        st_we    = '1;
        st_waddr = clr_q;
      end
      StFeed: begin
        if (fields && cfg_log2_h_i == 4'd1 && r_y == '0) st_we = mg_fed;
        st_waddr = {1'b0, r_x[0], r_x[ColW:1]};
        for (int p = 0; p < Planes; p++) begin
          st_wdata[p*ChW +: ChW] = r_texel[(Planes-1-p)*ChW +: ChW];
        end
      end
      StCapture: begin
        if (cap_in_line) st_we[cap_plane] = 1'b1;
        st_waddr = {line_a[1], o_bank[0], cap_col};
        st_wdata = {Planes{cap_value}};
      end
      default: ;
    endcase
  end

  // ---- Control ----------------------------------------------------------------------------------

  logic item_go;      // StItem: the dropped frame's flush (if any) is done
  logic begin_frame;  // ... and the item begins a frame
  logic rf_push, rf_pop;
  logic swap_now;     // StAccess: the pending frame is in the memory, its swap goes

  assign item_go     = !r_dropped || flush_ready;
  assign begin_frame = state_q == StItem && item_go && r_accepted && r_frame_start;
  // The rows' queue takes a read while it has room: so does the FIFO, to stay beside it.
  assign rf_push     = state_q == StReads && read_ready && rf_n_q != CountW'(ReadDepth);
  assign rf_pop      = capturing && cap_q == '1;
  assign swap_now    = pending_q && o_drained;

  function automatic logic [PtrW-1:0] next_ptr(input logic [PtrW-1:0] ptr);
    next_ptr = (ptr == PtrW'(ReadDepth - 1)) ? '0 : ptr + PtrW'(1);
  endfunction

  always_comb begin
    state_d    = state_q;
    clr_d      = clr_q;
    tag_d      = tag_q;
    cur_d      = cur_q;
    newest_d   = newest_q;
    pending_d  = pending_q;
    front_d    = front_q;
    swap_d     = swap_q;
    s_d        = s_q;
    lo_d       = lo_q;
    rb_d       = rb_q;
    plane_d    = plane_q;
    cap_d      = cap_q;
    beat_d     = beat_q;
    shown_d    = shown_q;
    overruns_d = overruns_q;
    late_d     = late_q;
    rf_head_d  = rf_pop ? next_ptr(rf_head_q) : rf_head_q;
    rf_tail_d  = rf_push ? next_ptr(rf_tail_q) : rf_tail_q;
    rf_n_d     = rf_n_q + CountW'(rf_push) - CountW'(rf_pop);

    if (begin_frame) begin
      // Tags 1 .. 0xFFFE, then 1 again (0xFFFF names no frame: golden frame_tag).
      tag_d = (tag_q == {{(TagW - 1){1'b1}}, 1'b0}) ? TagW'(1) : tag_q + TagW'(1);
      cur_d = !newest_q;
    end

    unique case (state_q)
      StClear: begin
        clr_d = clr_q + StoreAW'(1);  // back to 0 after the last word
        if (clr_q == '1) state_d = StIdle;
      end
      StIdle: begin
        if (restart) begin
          state_d   = StClear;
          tag_d     = '0;
          newest_d  = 1'b0;
          pending_d = 1'b0;
          front_d   = 1'b0;
          rf_head_d = '0;
          rf_tail_d = '0;
          rf_n_d    = '0;
        end else if (port_in_valid && port_in_ready) begin
          state_d = StItem;
        end else if (rows_cycle_valid && rows_cycle_ready) begin
          state_d = StAccess;
        end
      end
      StItem: begin
        if (item_go && r_accepted) state_d = StLine;
        else if (item_go) state_d = StDone;
      end
      StLine: begin
        if (late) late_d = late_q + StatW'(1);
        s_d     = first_row;
        lo_d    = first_row;
        rb_d    = 1'b0;
        if (need_reads) state_d = StReads;
        else state_d = StFeed;
      end
      StReads: begin
        if (read_ready) begin
          if (s_q != group_hi) begin  // the group's next row
            s_d = s_q + SegW'(1);
          end else if (!rb_q) begin   // the group again, in bank 1
            s_d  = lo_q;
            rb_d = 1'b1;
          end else if (last_row) begin
            state_d = StFeed;
          end else begin              // the next row, a group of its own
            s_d  = s_q + SegW'(1);
            lo_d = s_q + SegW'(1);
            rb_d = 1'b0;
          end
        end
      end
      StFeed: begin
        plane_d = '0;
        state_d = StDrain;
      end
      StDrain: begin
        // The plane's writes are done when its mipgen is idle (every item makes a write).
        if (!mg_wr_valid[plane_q]) begin
          plane_d = plane_q + 2'd1;
          if (plane_q == last_plane && r_frame_end) state_d = StEnd;
          else if (plane_q == last_plane) state_d = StDone;
        end
      end
      StEnd: begin
        if (flush_ready) begin
          if (pending_q) begin  // the memory cannot keep up: not shown
            overruns_d = overruns_q + StatW'(1);
            state_d    = StDone;
          end else begin
            newest_d  = cur_q;
            pending_d = 1'b1;
            state_d   = StHold;
          end
        end
      end
      StHold: begin
        if (hold_ready) state_d = StDone;
      end
      StDone: begin
        state_d = StIdle;
      end
      StAccess: begin
        // The pending frame's buffer is the newest: it becomes the front one.
        swap_d = swap_now;
        if (swap_now) begin
          pending_d = 1'b0;
          front_d   = newest_q;
          shown_d   = shown_q + StatW'(1);
        end
        cap_d  = '0;
        beat_d = BeatW'(1);
        if (o_read) state_d = StResp;
        else if (o_write && Beats > 1) state_d = StBeat;
        else if (swap_now) state_d = StUnhold;
        else state_d = StShow;
      end
      StBeat: begin
        beat_d = beat_q + BeatW'(1);
        if (o_read) state_d = StResp;
        else if (beat_q == BeatW'(Beats - 1) && swap_q) state_d = StUnhold;
        else if (beat_q == BeatW'(Beats - 1)) state_d = StShow;
      end
      StResp: begin
        if (mem_resp_valid_i) state_d = StCapture;
      end
      StCapture: begin
        cap_d = cap_q + CellBits'(1);
        if (cap_q == '1 && swap_q) state_d = StUnhold;
        else if (cap_q == '1) state_d = StShow;
        else if (cap_q[2:0] == 3'd7) state_d = StBeat;  // the next word's read
      end
      StUnhold: begin
        if (hold_ready) state_d = StShow;
      end
      StShow: begin
        if (out_ready_i) state_d = StIdle;
      end
      default: state_d = StIdle;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q    <= StClear;
      clr_q      <= '0;
      tag_q      <= '0;
      cur_q      <= 1'b0;
      newest_q   <= 1'b0;
      pending_q  <= 1'b0;
      front_q    <= 1'b0;
      rf_head_q  <= '0;
      rf_tail_q  <= '0;
      rf_n_q     <= '0;
      shown_q    <= '0;
      overruns_q <= '0;
      late_q     <= '0;
    end else begin
      state_q    <= state_d;
      clr_q      <= clr_d;
      tag_q      <= tag_d;
      cur_q      <= cur_d;
      newest_q   <= newest_d;
      pending_q  <= pending_d;
      front_q    <= front_d;
      rf_head_q  <= rf_head_d;
      rf_tail_q  <= rf_tail_d;
      rf_n_q     <= rf_n_d;
      shown_q    <= shown_d;
      overruns_q <= overruns_d;
      late_q     <= late_d;
    end
  end

  // Data without reset, each observed only in the states that follow its load: cfg_q (loaded
  // through StClear, which follows every reset), the item's and access's counters and swap,
  // the response, the FIFO's entries below its count.
  always_ff @(posedge clk_i) begin
    if (state_q == StClear) cfg_q <= cfg;
    swap_q  <= swap_d;
    s_q     <= s_d;
    lo_q    <= lo_d;
    rb_q    <= rb_d;
    plane_q <= plane_d;
    cap_q   <= cap_d;
    beat_q  <= beat_d;
    if (state_q == StResp && mem_resp_valid_i) resp_q <= mem_resp_data_i;
    if (rf_push) begin
      rf_line_q[rf_tail_q] <= read_line;
      rf_buf_q[rf_tail_q]  <= cur_q;
    end
  end

  assign stat_frames_shown_o   = shown_q;
  assign stat_frames_dropped_o = port_dropped;
  assign stat_overruns_o       = overruns_q;
  assign stat_late_reads_o     = late_q;

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // An item's states hold the port's output.
  a_item_held: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (state_q inside {StItem, StLine, StReads, StFeed, StDrain, StEnd, StHold, StDone}) |->
      port_out_valid);
  // The rows' read queue has room for every read (golden's is unbounded).
  a_read_room: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (state_q == StReads && read_ready) |-> rf_n_q != CountW'(ReadDepth));
  // The mipgens are idle when a texel is fed (each drained its writes).
  a_feed_idle: assert property (@(posedge clk_i) disable iff (!rst_ni)
      state_q == StFeed |-> (mg_in_ready & mg_fed) == mg_fed);
  // A read has a line to capture; responses come only for reads.
  a_read_line: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (state_q == StAccess && o_read) |-> rf_n_q != '0);
  a_resp_awaited: assert property (@(posedge clk_i) disable iff (!rst_ni)
      mem_resp_valid_i |-> state_q == StResp);
  // Nothing holds the rows from StClear's cycle (every item before it is done).
  a_close_taken: assert property (@(posedge clk_i) disable iff (!rst_ni)
      close_pages |-> rows_cycle_ready);
  // The cycle item's output is there from StAccess until taken.
  a_access_held: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (state_q inside {StAccess, StBeat, StResp, StCapture, StUnhold, StShow}) |-> o_valid);
`endif

endmodule
