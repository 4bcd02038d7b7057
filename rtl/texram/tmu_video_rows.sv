/// The video path's page-row buffers and write arbiter of the TEXRAM (000 §11-12; docs/video.md):
/// the mipmap generator's cell writes are collected per bank into row buffers, and a buffer is
/// written to its bank in one masked access in a memory cycle the sampler does not want, or
/// after it has waited L cycles (the sampler then loses the cycle). Bit-exact and cycle-exact
/// with the golden texram::video::RowBuffers (golden/texram/video/row_buffers.hpp) at
/// segment_cells = Cells and buffers_per_bank = Buffers.
///
/// Items, at most one a clock (a fixed priority: put, flush, hold, read, cycle):
///   put    a cell write (bank, address, value) of frame `tag`: into the bank's buffer
///          collecting that row for that frame, else its first free buffer, else lost
///          (counted); a buffer whose every cell is written becomes ready (queued).
///   flush  frame `tag` ends: each buffer collecting for it becomes ready, one a clock in
///          buffer order (the item is taken when none is left).
///   hold   the swap barrier: ready buffers of frames after `tag` wait (0xFFFF: none).
/// Tags wrap (golden frame_tag: 1 .. 0xFFFE, then 1) and compare as serial numbers: a is b or
/// later when a - b, modulo 2^16, is below 0x8000 (the frames in the rows at once are a few).
///   read   a row read for the line above (bank, the row's address), queued (ReadDepth).
///   cycle  one memory cycle; `sampler`: the sampler wants it. Its output: whether the sampler
///          got it, and the access started in it (a read's mask and data: the cells of the row a
///          buffer still holds, the newest buffer's, which the read takes instead of the
///          memory's), and whether no buffer of the held frame is left after it (drained). In order: (1) the oldest read, if the
///          sampler does not want the cycle or the read has waited cfg_read_wait_i; else (2) the
///          oldest ready buffer not held, if the sampler does not want the cycle or it has
///          waited cfg_max_wait_i (L); else (3) the sampler, if it wants it. An access takes
///          a second cycle on a page fault (its bank's open page differs), which the sampler
///          loses too; a sampler access closes every bank's page.
/// Waits count cycle items and saturate at 16 bits (exact against any bound up to 0xFFFF).
///
/// Storage: Banks x Buffers rows of Cells bytes and a written mask; the ready queue (buffer,
/// frame tag, wait), shifted down when an entry leaves from its middle (a held frame's
/// buffers stay behind the ones taken); the read queue (bank, row, wait).
///
/// Example (Cells 8, L 4, sampler at every cycle): 8 puts to bank 1 at 512..519 make buffer 8
/// ready; cycle items 0..3 are the sampler's (granted), item 4 starts the write (wait 4, a
/// page fault: the sampler moved the pages), item 5 is its second cycle (the sampler loses
/// both), item 6 the sampler's again.
module tmu_video_rows #(
  /// Cells of a row buffer (a power of two up to 512; the golden figures use 512, a page).
  parameter int unsigned Cells     = 8,
  /// Row buffers of each bank.
  parameter int unsigned Buffers   = 8,
  /// Entries of the read queue.
  parameter int unsigned ReadDepth = 8
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,

  /// L, and the read bound, in cycles.
  input  tmu_pkg::video_tag_t   cfg_max_wait_i,
  input  tmu_pkg::video_tag_t   cfg_read_wait_i,

  input  logic                  put_valid_i,
  output logic                  put_ready_o,
  input  tmu_pkg::bank_t        put_bank_i,
  input  tmu_pkg::bank_addr_t   put_addr_i,
  input  tmu_pkg::channel_t     put_value_i,
  input  tmu_pkg::video_tag_t   put_tag_i,

  input  logic                  flush_valid_i,
  output logic                  flush_ready_o,
  input  tmu_pkg::video_tag_t   flush_tag_i,

  input  logic                  hold_valid_i,
  output logic                  hold_ready_o,
  input  tmu_pkg::video_tag_t   hold_tag_i,

  input  logic                  read_valid_i,
  output logic                  read_ready_o,
  input  tmu_pkg::bank_t        read_bank_i,
  input  tmu_pkg::bank_addr_t   read_addr_i,  // its low bits (a cell in the row) unused

  input  logic                  cycle_valid_i,
  output logic                  cycle_ready_o,
  input  logic                  cycle_sampler_i,

  /// Per cycle item: the sampler got the cycle; a write or read started (its page fault, bank,
  /// the row's first cell, the cells written and their bytes, its wait).
  output logic                  out_valid_o,
  input  logic                  out_ready_i,
  output logic                  out_granted_o,
  output logic                  out_write_o,
  output logic                  out_read_o,
  output logic                  out_fault_o,
  output tmu_pkg::bank_t        out_bank_o,
  output tmu_pkg::bank_addr_t   out_addr_o,
  output logic [Cells-1:0]      out_mask_o,
  output logic [8*Cells-1:0]    out_data_o,
  output tmu_pkg::video_tag_t   out_wait_o,
  /// After the cycle no buffer holds a cell of the frame the hold item names (its swap may go).
  output logic                  out_drained_o,

  /// Counters (32 bits, wrapping; the most-at-once ones are high-water marks).
  output tmu_pkg::stat_count_t  stat_cells_in_o,
  output tmu_pkg::stat_count_t  stat_lost_writes_o,
  output tmu_pkg::stat_count_t  stat_forced_o,
  output tmu_pkg::stat_count_t  stat_max_ready_o,
  output tmu_pkg::stat_count_t  stat_max_busy_bank_o
);

  localparam int unsigned Banks   = 8;
  localparam int unsigned NB      = Banks * Buffers;
  localparam int unsigned IdW     = $clog2(NB);
  localparam int unsigned SelW    = (Buffers > 1) ? $clog2(Buffers) : 1;
  localparam int unsigned CellW   = (Cells > 1) ? $clog2(Cells) : 1;
  localparam int unsigned CellBits = $clog2(Cells);
  localparam int unsigned AddrW   = tmu_pkg::BankAddrW;
  localparam int unsigned SegW    = AddrW - CellBits;
  localparam int unsigned PageW   = AddrW - tmu_pkg::PageLog2;
  localparam int unsigned TagW    = tmu_pkg::VideoTagW;
  localparam int unsigned StatW   = tmu_pkg::StatCountW;
  localparam int unsigned QW      = $clog2(NB + 1);
  localparam int unsigned RW      = $clog2(ReadDepth + 1);
  localparam int unsigned BusyW   = $clog2(Buffers + 1);

  if (Buffers < 2 || (Buffers & (Buffers - 1)) != 0) begin : gen_check_buffers
    $error("tmu_video_rows: Buffers must be a power of two, 2 or more");
  end
  if (Cells < 2 || Cells > (1 << tmu_pkg::PageLog2) || (Cells & (Cells - 1)) != 0) begin : gen_check
    $error("tmu_video_rows: Cells must be a power of two, 2..512");
  end

  typedef enum logic [1:0] { Free = 2'd0, Collecting = 2'd1, Ready = 2'd2, Writing = 2'd3 } state_e;

  // ---- Storage -------------------------------------------------------------------------------

  state_e              st_q    [NB];
  logic [SegW-1:0]     seg_q   [NB];
  logic [TagW-1:0]     tag_q   [NB];
  logic [Cells-1:0]    valid_q [NB];
  logic [8*Cells-1:0]  data_q  [NB];

  // The ready queue, oldest first; entries at rq_n_q and above are meaningless.
  logic [IdW-1:0]      rq_id_q  [NB];
  logic [TagW-1:0]     rq_tag_q [NB];
  logic [TagW-1:0]     rq_age_q [NB];
  logic [QW-1:0]       rq_n_q;

  logic [2:0]          rd_bank_q [ReadDepth];
  logic [SegW-1:0]     rd_seg_q  [ReadDepth];
  logic [TagW-1:0]     rd_age_q  [ReadDepth];
  logic [RW-1:0]       rd_n_q;

  logic [Banks-1:0]    open_v_q;
  logic [PageW-1:0]    open_pg_q [Banks];

  logic [1:0]          busy_q;     // cycles left of the access in progress
  logic                reading_q;  // ... which is a read
  logic [IdW-1:0]      writing_q;  // ... else the buffer it writes
  logic [TagW-1:0]     hold_q;

  tmu_pkg::stat_count_t cells_in_q, lost_q, forced_q, max_ready_q, max_busy_q;

  // ---- Handshakes: one item a clock --------------------------------------------------------

  logic put_fire, flush_fire, hold_fire, read_fire, cycle_fire;
  logic flush_any;   // a buffer collecting for flush_tag_i is left
  logic [IdW-1:0] flush_id;

  assign put_ready_o   = 1'b1;
  assign flush_ready_o = !put_valid_i && !flush_any;
  assign hold_ready_o  = !put_valid_i && !flush_valid_i;
  assign read_ready_o  = !put_valid_i && !flush_valid_i && !hold_valid_i;
  assign cycle_ready_o = !put_valid_i && !flush_valid_i && !hold_valid_i && !read_valid_i &&
                         (!out_valid_o || out_ready_i);
  assign put_fire      = put_valid_i;
  assign flush_fire    = flush_valid_i && !put_valid_i;  // a step: one buffer made ready
  assign hold_fire     = hold_valid_i && hold_ready_o;
  assign read_fire     = read_valid_i && read_ready_o;
  assign cycle_fire    = cycle_valid_i && cycle_ready_o;

  always_comb begin
    flush_any = 1'b0;
    flush_id  = '0;
    for (int i = NB - 1; i >= 0; i--) begin
      if (st_q[i] == Collecting && tag_q[i] == flush_tag_i) begin
        flush_any = 1'b1;
        flush_id  = IdW'(i);
      end
    end
  end

  logic unused_read_cell;
  assign unused_read_cell = ^read_addr_i[CellBits-1:0];

  // ---- put: the bank's buffer for the row and frame, else its first free one -------------

  logic [SegW-1:0]  put_seg;
  logic [CellW-1:0] put_cell;
  logic             put_hit, put_free;
  logic [SelW-1:0]  put_hit_j, put_free_j;
  logic [IdW-1:0]   put_id;
  logic [Cells-1:0] put_valid_new;

  logic [IdW-1:0]   put_base;  // the bank's first buffer

  assign put_base = IdW'(put_bank_i) << SelW;
  assign put_seg  = put_addr_i[AddrW-1:CellBits];
  assign put_cell = CellW'(put_addr_i[CellBits-1:0]);

  always_comb begin
    put_hit    = 1'b0;
    put_free   = 1'b0;
    put_hit_j  = '0;
    put_free_j = '0;
    for (int j = Buffers - 1; j >= 0; j--) begin
      if (st_q[put_base + IdW'(j)] == Collecting &&
          seg_q[put_base + IdW'(j)] == put_seg &&
          tag_q[put_base + IdW'(j)] == put_tag_i) begin
        put_hit   = 1'b1;
        put_hit_j = SelW'(j);
      end
      if (st_q[put_base + IdW'(j)] == Free) begin
        put_free   = 1'b1;
        put_free_j = SelW'(j);
      end
    end
    put_id        = put_base + (put_hit ? IdW'(put_hit_j) : IdW'(put_free_j));
    put_valid_new = (put_hit ? valid_q[put_id] : '0) | (Cells'(1) << put_cell);
  end

  // ---- cycle: the arbiter ------------------------------------------------------------------

  logic            sampler;
  logic            rd_go, wr_go, start, fault, granted;
  logic            wr_found;
  logic [QW-1:0]   wr_k;
  logic [IdW-1:0]  wr_id;
  logic [2:0]      acc_bank;
  logic [SegW-1:0] acc_seg;
  logic [PageW-1:0] acc_page;
  logic [1:0]      busy_now, busy_next;
  logic            reading_now;
  logic [IdW-1:0]  writing_now;
  logic            freeing;  // the write in progress ends in this cycle: its buffer is free

  assign sampler = cycle_sampler_i;

  // Tag a is tag b or a later frame's (golden tag_not_before).
  function automatic logic not_before(input logic [TagW-1:0] a, input logic [TagW-1:0] b);
    logic [TagW-1:0] d;
    d = a - b;
    not_before = !d[TagW-1];
  endfunction

  always_comb begin
    wr_found = 1'b0;
    wr_k     = '0;
    for (int k = NB - 1; k >= 0; k--) begin
      if (QW'(k) < rq_n_q && (hold_q == '1 || not_before(hold_q, rq_tag_q[k]))) begin
        wr_found = 1'b1;
        wr_k     = QW'(k);
      end
    end
  end

  assign wr_id    = rq_id_q[wr_k[IdW-1:0]];
  assign rd_go    = busy_q == '0 && rd_n_q != '0 && (!sampler || rd_age_q[0] >= cfg_read_wait_i);
  assign wr_go    = busy_q == '0 && !rd_go && wr_found &&
                    (!sampler || rq_age_q[wr_k[IdW-1:0]] >= cfg_max_wait_i);
  assign start    = rd_go || wr_go;
  assign acc_bank = rd_go ? rd_bank_q[0] : wr_id[IdW-1:IdW-3];
  assign acc_seg  = rd_go ? rd_seg_q[0] : seg_q[wr_id];
  assign acc_page = acc_seg[SegW-1:SegW-PageW];
  assign fault    = !open_v_q[acc_bank] || open_pg_q[acc_bank] != acc_page;
  assign busy_now = start ? (fault ? 2'd2 : 2'd1) : busy_q;
  assign busy_next = (busy_now != '0) ? busy_now - 2'd1 : 2'd0;
  assign reading_now = start ? rd_go : reading_q;
  assign writing_now = wr_go ? wr_id : writing_q;
  assign freeing  = busy_now != '0 && busy_next == '0 && !reading_now;
  assign granted  = busy_now == '0 && sampler;

  // A read's data take the cells a row buffer still holds: per cell, the newest buffer of the
  // bank holding that row's cell (highest tag, then the last), as golden's newest_holding. Only
  // a pending read is looked at (rd_go needs one): the condition spares the simulation the
  // search at every clock; the logic is the same.
  logic [Cells-1:0]   rd_mask;
  logic [8*Cells-1:0] rd_data;
  logic [TagW-1:0]    rd_best [Cells];
  logic [IdW-1:0]     rd_id;

  always_comb begin
    rd_mask = '0;
    rd_data = '0;
    rd_id   = '0;
    for (int c = 0; c < Cells; c++) rd_best[c] = '0;
    if (rd_n_q != '0) begin
      for (int c = 0; c < Cells; c++) begin
        for (int j = 0; j < Buffers; j++) begin
          rd_id = (IdW'(rd_bank_q[0]) << SelW) + IdW'(j);
          if (st_q[rd_id] != Free && seg_q[rd_id] == rd_seg_q[0] && valid_q[rd_id][c] &&
              (!rd_mask[c] || not_before(tag_q[rd_id], rd_best[c]))) begin
            rd_mask[c]        = 1'b1;
            rd_best[c]        = tag_q[rd_id];
            rd_data[8*c +: 8] = data_q[rd_id][8*c +: 8];
          end
        end
      end
    end
  end

  // Drained: no buffer of the held frame is busy after this cycle (a write that ends in it has
  // freed its buffer).
  logic drained;

  always_comb begin
    drained = 1'b1;
    for (int i = 0; i < NB; i++) begin
      if (st_q[i] != Free && tag_q[i] == hold_q && !(freeing && IdW'(i) == writing_now)) begin
        drained = 1'b0;
      end
    end
  end

  // ---- Next state of the queues -------------------------------------------------------------

  logic [IdW-1:0]  rq_id_d  [NB];
  logic [TagW-1:0] rq_tag_d [NB];
  logic [TagW-1:0] rq_age_d [NB];
  logic [QW-1:0]   rq_n_d;
  logic            push;
  logic [IdW-1:0]  push_id;

  assign push    = (put_fire && (put_hit || put_free) && put_valid_new == '1) ||
                   (flush_fire && flush_any);
  assign push_id = put_fire ? put_id : flush_id;

  // A wait one cycle longer, saturating.
  function automatic logic [TagW-1:0] older(input logic [TagW-1:0] age);
    older = (age == {TagW{1'b1}}) ? age : age + TagW'(1);
  endfunction

  always_comb begin
    for (int k = 0; k < NB; k++) begin
      rq_id_d[k]  = rq_id_q[k];
      rq_tag_d[k] = rq_tag_q[k];
      rq_age_d[k] = rq_age_q[k];
    end
    rq_n_d = rq_n_q;
    if (push) begin
      rq_id_d[rq_n_q[IdW-1:0]]  = push_id;
      rq_tag_d[rq_n_q[IdW-1:0]] = put_fire ? put_tag_i : flush_tag_i;
      rq_age_d[rq_n_q[IdW-1:0]] = '0;
      rq_n_d = rq_n_q + QW'(1);
    end else if (cycle_fire) begin
      // The written entry leaves; the ones behind it move up; every one waited a cycle.
      for (int k = 0; k < NB; k++) begin
        if (wr_go && QW'(k) >= wr_k && k + 1 < NB) begin
          rq_id_d[k]  = rq_id_q[k+1];
          rq_tag_d[k] = rq_tag_q[k+1];
          rq_age_d[k] = older(rq_age_q[k+1]);
        end else begin
          rq_age_d[k] = older(rq_age_q[k]);
        end
      end
      if (wr_go) rq_n_d = rq_n_q - QW'(1);
    end
  end

  // ---- Registers ----------------------------------------------------------------------------

  logic [BusyW-1:0] bank_busy [Banks];
  logic [BusyW-1:0] most_busy;

  always_comb begin
    most_busy = '0;
    for (int b = 0; b < Banks; b++) begin
      bank_busy[b] = '0;
      for (int j = 0; j < Buffers; j++) begin
        bank_busy[b] = bank_busy[b] + BusyW'(st_q[b * Buffers + j] != Free);
      end
      if (bank_busy[b] > most_busy) most_busy = bank_busy[b];
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      for (int i = 0; i < NB; i++) st_q[i] <= Free;
      rq_n_q      <= '0;
      rd_n_q      <= '0;
      open_v_q    <= '0;
      busy_q      <= '0;
      reading_q   <= 1'b0;
      hold_q      <= '1;
      out_valid_o <= 1'b0;
      cells_in_q  <= '0;
      lost_q      <= '0;
      forced_q    <= '0;
      max_ready_q <= '0;
      max_busy_q  <= '0;
    end else begin
      rq_n_q <= rq_n_d;
      if (StatW'(rq_n_q) > max_ready_q) max_ready_q <= StatW'(rq_n_q);
      if (StatW'(most_busy) > max_busy_q) max_busy_q <= StatW'(most_busy);
      if (put_fire) begin
        cells_in_q <= cells_in_q + StatW'(1);
        if (!put_hit && !put_free) lost_q <= lost_q + StatW'(1);
        else if (put_valid_new == '1) st_q[put_id] <= Ready;
        else if (!put_hit) st_q[put_id] <= Collecting;
      end
      if (flush_fire && flush_any) st_q[flush_id] <= Ready;
      if (hold_fire) hold_q <= hold_tag_i;
      if (read_fire && rd_n_q != RW'(ReadDepth)) rd_n_q <= rd_n_q + RW'(1);
      if (cycle_fire) begin
        if (rd_go) rd_n_q <= rd_n_q - RW'(1);
        if (wr_go) st_q[wr_id] <= Writing;
        if (freeing) st_q[writing_now] <= Free;
        if (start) begin
          open_v_q[acc_bank]  <= 1'b1;
          open_pg_q[acc_bank] <= acc_page;
        end else if (granted) begin
          open_v_q <= '0;
        end
        busy_q    <= busy_next;
        reading_q <= (busy_next != '0) && reading_now;
        if (start && sampler) forced_q <= forced_q + StatW'(1);
      end
      if (cycle_fire) out_valid_o <= 1'b1;
      else if (out_ready_i) out_valid_o <= 1'b0;
    end
  end

  // Data without reset: a buffer's mask is cleared when it is taken, its bytes only read under
  // the mask; queue entries only below the counts.
  always_ff @(posedge clk_i) begin
    for (int k = 0; k < NB; k++) begin
      rq_id_q[k]  <= rq_id_d[k];
      rq_tag_q[k] <= rq_tag_d[k];
      rq_age_q[k] <= rq_age_d[k];
    end
    if (put_fire && (put_hit || put_free)) begin
      seg_q[put_id]   <= put_seg;
      tag_q[put_id]   <= put_tag_i;
      valid_q[put_id] <= put_valid_new;
      data_q[put_id][8*put_cell +: 8] <= put_value_i;
    end
    writing_q <= (cycle_fire) ? writing_now : writing_q;
    if (read_fire && rd_n_q != RW'(ReadDepth)) begin
      rd_bank_q[rd_n_q[$clog2(ReadDepth)-1:0]] <= read_bank_i;
      rd_seg_q[rd_n_q[$clog2(ReadDepth)-1:0]]  <= read_addr_i[AddrW-1:CellBits];
      rd_age_q[rd_n_q[$clog2(ReadDepth)-1:0]]  <= '0;
    end else if (cycle_fire) begin
      for (int r = 0; r < ReadDepth; r++) begin
        if (rd_go && r + 1 < ReadDepth) begin
          rd_bank_q[r] <= rd_bank_q[r+1];
          rd_seg_q[r]  <= rd_seg_q[r+1];
          rd_age_q[r]  <= older(rd_age_q[r+1]);
        end else begin
          rd_age_q[r] <= older(rd_age_q[r]);
        end
      end
    end
    if (cycle_fire) begin
      out_granted_o <= granted;
      out_write_o   <= wr_go;
      out_read_o    <= rd_go;
      out_fault_o   <= start && fault;
      out_bank_o    <= start ? acc_bank : '0;
      out_addr_o    <= start ? {acc_seg, {CellBits{1'b0}}} : '0;
      out_mask_o    <= wr_go ? valid_q[wr_id] : (rd_go ? rd_mask : '0);
      // (Three branches rather than one expression per cell: the same logic, a cheaper
      // simulation at rows of a page.)
      if (wr_go) begin
        for (int c = 0; c < Cells; c++) begin
          out_data_o[8*c +: 8] <= valid_q[wr_id][c] ? data_q[wr_id][8*c +: 8] : 8'h00;
        end
      end else if (rd_go) begin
        out_data_o <= rd_data;
      end else begin
        out_data_o <= '0;
      end
      out_drained_o <= drained;
      out_wait_o    <= rd_go ? rd_age_q[0] : (wr_go ? rq_age_q[wr_k[IdW-1:0]] : '0);
    end
  end

  assign stat_cells_in_o      = cells_in_q;
  assign stat_lost_writes_o   = lost_q;
  assign stat_forced_o        = forced_q;
  assign stat_max_ready_o     = max_ready_q;
  assign stat_max_busy_bank_o = max_busy_q;

endmodule
