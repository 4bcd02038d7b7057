/// The low-cost CCC texture unit (000 §4, Figs. 6 and 7): a 4-entry direct-mapped cache of
/// decoded CCC blocks with neighbour lookahead, feeding a bilinear interpolator. Bit-exact
/// with the golden model ccc::CacheBilinearUnit (golden/ccc/ccc_cache_bilinear.hpp), whose
/// header defines the footprint, the clamp-to-edge rule, the cache and the lookahead.
///
/// A request (u, v) (SQ16.8 texels) takes the four texels around (u - 0.5, v - 0.5),
/// clamped to the texture. Their 1, 2 or 4 distinct blocks are looked up in the cache; entry
/// (slot) of block (bx, by) is (bx & 1) + 2 (by & 1) (Fig. 7), so a footprint's blocks never
/// compete for an entry. A missing block is fetched from the texture memory into register
/// 608 (blk_q), its colours a and b are looked up in the single-port CLUT one after the other
/// (the 2:1 multiplexer 610), and the entry is written with both colours and the decision
/// bits. When every block is present the blend of the four texels goes to the output
/// register. Then, if cfg_lookahead_i is set, the up to three blocks adjacent to the quadrant
/// of the point's texel that are not present are fetched the same way while the memory would
/// otherwise be idle (the output may be waiting for out_ready_i meanwhile); the next request
/// is looked up only when that is done, so the statistics do not depend on timing.
///
/// An entry's tag is its block coordinates (bx, by): while the texture size is held, they
/// name the same block as the golden model's tag, the block address by * ceil(w/4) + bx.
///
/// FSM:
///   StIdle    accepts a CLUT write or a request (a request is also accepted by the cycle
///             that finishes the previous one in StLookup / StBlend)
///   StLookup  all footprint blocks compared at once; hits and misses counted. If none is
///             missing, the blend is loaded into the output (when it is free) and the
///             lookahead candidates are compared (prefetches counted)
///   StMemReq  mem_req_valid_o until mem_req_ready_i
///   StMemWait until mem_resp_valid_i; the block word goes to blk_q (register 608)
///   StClutA   CLUT read of colour a
///   StClutB   CLUT read of colour b; colour a to the entry
///   StFill    colour b, decision bits and tag to the entry; then the next missing block,
///             StBlend (footprint complete) or StIdle (lookahead complete)
///   StBlend   the blend half of StLookup, after fills or while the output is full
/// Cycle costs, with out_ready_i and mem_req_ready_i high and a memory latency of L >= 1
/// cycles (request fired to response valid):
///   all blocks hit, nothing to prefetch   1 cycle per request (back to back)
///   each footprint or lookahead fill      4 + L cycles (StMemReq, L x StMemWait, StClutA,
///                                         StClutB, StFill)
///   after the footprint's fills           +1 (StBlend)
///   after a lookahead fetch               +1 (StIdle accepts the next request)
/// e.g. 8 x 8 texture, empty cache, L = 1: (u, v) = (4.0, 2.0) misses blocks (0,0) and (1,0),
/// the output is valid 13 cycles after the request was accepted (1 + 2 x 5 + 1 + 1), then
/// the lookahead fetches (1,1) and (0,1): the next request is accepted 23 cycles after it.
///
/// The statistics count at the decision: hits and misses in StLookup, prefetches when the
/// blend is loaded.
///
/// The configuration (cfg_*) is quasi-static: hold it for the whole run, from before reset.
/// The CLUT is a single-port RAM without reset: write every entry a block will use.
///
/// Example (8 x 8 texture, lookahead on, empty cache): u = v = 3.75 (raw 0x3C0) has the
/// footprint x0 = y0 = 3, x1 = y1 = 4, fx = fy = 0x40: blocks (0,0), (1,0), (0,1), (1,1),
/// four misses; the texel (3, 3) is in the far quadrant of block (0,0), whose neighbours
/// are the same blocks, already present: no prefetch.
module tmu_ccc_cache_bilinear (
  input  logic                     clk_i,
  input  logic                     rst_ni,

  /// Texture size in texels (1..4096) and lookahead enable; held for the whole run.
  input  tmu_pkg::tex_size_t       cfg_width_i,
  input  tmu_pkg::tex_size_t       cfg_height_i,
  input  logic                     cfg_lookahead_i,

  /// CLUT write: entry clut_addr_i <= clut_rgb_i. Ready only while the unit is idle, so a
  /// write is ordered with the requests around it; it invalidates every cache entry.
  input  logic                     clut_valid_i,
  output logic                     clut_ready_o,
  input  tmu_pkg::clut_index_t     clut_addr_i,
  input  tmu_pkg::rgb888_t         clut_rgb_i,

  /// Sample request: the point (u, v) in texels of the texture, SQ16.8.
  input  logic                     req_valid_i,
  output logic                     req_ready_o,
  input  tmu_pkg::tex_coord_t      req_u_i,
  input  tmu_pkg::tex_coord_t      req_v_i,

  /// Texture memory read request (one outstanding) of block word mem_req_addr_o ...
  output logic                     mem_req_valid_o,
  input  logic                     mem_req_ready_i,
  output tmu_pkg::ccc_block_addr_t mem_req_addr_o,
  /// ... and its response, one or more cycles after the request fired (no ready).
  input  logic                     mem_resp_valid_i,
  input  tmu_pkg::ccc_block_t      mem_resp_block_i,

  /// Bilinear sample, one per request, in request order.
  output logic                     out_valid_o,
  input  logic                     out_ready_i,
  output tmu_pkg::rgb888_t         out_rgb_o,

  /// Statistics since reset: footprint blocks found, fetched, and lookahead blocks fetched.
  output tmu_pkg::stat_count_t     stat_hits_o,
  output tmu_pkg::stat_count_t     stat_misses_o,
  output tmu_pkg::stat_count_t     stat_prefetches_o
);

  localparam int unsigned TexelW   = 12;  // texel coordinate 0..4095 (MaxTexSize)
  localparam int unsigned BlockW   = 10;  // block coordinate 0..1023
  localparam int unsigned TagW     = 2 * BlockW;
  localparam int unsigned SizeW    = tmu_pkg::TexSizeW;
  localparam int unsigned AddrW    = tmu_pkg::CccBlockAddrW;
  localparam int unsigned Entries  = tmu_pkg::CccCacheEntries;
  localparam int unsigned SlotW    = $clog2(Entries);
  localparam int unsigned NumFp    = 4;   // footprint candidates: (x0,y0) (x1,y0) (x0,y1) (x1,y1)
  localparam int unsigned NumAhead = 3;   // lookahead: horizontal, vertical, diagonal
  localparam int unsigned NumCand  = NumFp + NumAhead;
  localparam int unsigned CandW    = $clog2(NumCand);
  localparam int unsigned StatW    = tmu_pkg::StatCountW;
  localparam int unsigned RgbW     = tmu_pkg::Rgb888W;
  localparam int unsigned ChW      = tmu_pkg::ChannelW;

  if (Entries != 4 || (1 << TexelW) != tmu_pkg::MaxTexSize || tmu_pkg::CccBlockSide != 4 ||
      AddrW != TagW) begin : gen_check_formats
    $error("tmu_ccc_cache_bilinear: the cache is built for 4 entries of 4x4 blocks, 4096^2 texels");
  end

  typedef enum logic [2:0] {
    StIdle,
    StLookup,
    StMemReq,
    StMemWait,
    StClutA,
    StClutB,
    StFill,
    StBlend
  } state_e;

  // ---- Footprint of the presented request -------------------------------------------------

  logic [TexelW-1:0]       req_x0, req_x1, req_y0, req_y1;
  tmu_pkg::filter_weight_t req_fx, req_fy;
  logic [BlockW-1:0]       req_bx, req_by, req_nbx, req_nby;
  logic                    req_nbx_in, req_nby_in;

  tmu_ccc_footprint_axis u_axis_u (
    .coord_i  (req_u_i),
    .size_i   (cfg_width_i),
    .t0_o     (req_x0),
    .t1_o     (req_x1),
    .frac_o   (req_fx),
    .blk_o    (req_bx),
    .nbr_o    (req_nbx),
    .nbr_in_o (req_nbx_in)
  );

  tmu_ccc_footprint_axis u_axis_v (
    .coord_i  (req_v_i),
    .size_i   (cfg_height_i),
    .t0_o     (req_y0),
    .t1_o     (req_y1),
    .frac_o   (req_fy),
    .blk_o    (req_by),
    .nbr_o    (req_nby),
    .nbr_in_o (req_nby_in)
  );

  // ---- State --------------------------------------------------------------------------------

  state_e                  state_q, state_d;
  // The accepted request: footprint and lookahead blocks.
  logic [TexelW-1:0]       x0_q, x1_q, y0_q, y1_q;
  tmu_pkg::filter_weight_t fx_q, fy_q;
  logic [BlockW-1:0]       bx_q, by_q, nbx_q, nby_q;
  logic                    nbx_in_q, nby_in_q;
  // Fill engine: candidates still to fetch, the one being fetched, its address, register 608.
  logic [NumCand-1:0]      miss_q, miss_d;
  logic [CandW-1:0]        cur_q, cur_d;
  tmu_pkg::ccc_block_addr_t mem_addr_q, mem_addr_d;
  tmu_pkg::ccc_block_t     blk_q;
  // The cache (Fig. 7): valid bits with reset, contents without (read only when valid).
  logic [Entries-1:0]      entry_valid_q, entry_valid_d;
  logic [TagW-1:0]         entry_tag_q    [Entries];  // {by, bx}
  tmu_pkg::rgb888_t        entry_a_q      [Entries];
  tmu_pkg::rgb888_t        entry_b_q      [Entries];
  logic [15:0]             entry_bits_q   [Entries];
  // The CLUT (612), single port, and its registered read data.
  tmu_pkg::rgb888_t        clut_q [tmu_pkg::ClutEntries];
  tmu_pkg::rgb888_t        clut_rdata_q;
  // Output register and statistics.
  logic                    out_valid_q, out_valid_d;
  tmu_pkg::rgb888_t        out_rgb_q;
  logic [StatW-1:0]        hits_q, hits_d, misses_q, misses_d, prefetches_q, prefetches_d;

  // ---- Lookup: the candidates and whether each is present ------------------------------------

  // Block {by, bx} of candidate k: 0..3 the footprint's (x0,y0), (x1,y0), (x0,y1), (x1,y1)
  // (block columns fbx0/fbx1, rows fby0/fby1); 4..6 the lookahead's horizontal (nbx,by),
  // vertical (bx,nby) and diagonal (nbx,nby).
  function automatic logic [TagW-1:0] cand_block(
      logic [CandW-1:0] k, logic [BlockW-1:0] fbx0, logic [BlockW-1:0] fbx1,
      logic [BlockW-1:0] fby0, logic [BlockW-1:0] fby1, logic [BlockW-1:0] bx,
      logic [BlockW-1:0] by, logic [BlockW-1:0] nbx, logic [BlockW-1:0] nby);
    logic [BlockW-1:0] cx, cy;
    if (k < CandW'(NumFp)) begin
      cx = k[0] ? fbx1 : fbx0;
      cy = k[1] ? fby1 : fby0;
    end else begin
      cx = (k == CandW'(NumFp + 1)) ? bx : nbx;
      cy = (k == CandW'(NumFp)) ? by : nby;
    end
    cand_block = {cy, cx};
  endfunction

  // Entry (slot) of a block: (bx & 1) + 2 (by & 1).
  function automatic logic [SlotW-1:0] slot_of(logic [TagW-1:0] blk);
    slot_of = {blk[BlockW], blk[0]};
  endfunction

  // Index of the first set bit of m (lookup order); 0 when none is set.
  function automatic logic [CandW-1:0] first_set(logic [NumCand-1:0] m);
    first_set = '0;
    for (int k = NumCand - 1; k >= 0; k--) begin
      if (m[k]) first_set = CandW'(k);
    end
  endfunction

  function automatic logic [2:0] count_ones(logic [NumFp-1:0] m);
    count_ones = 3'(m[0]) + 3'(m[1]) + 3'(m[2]) + 3'(m[3]);
  endfunction

  logic [BlockW-1:0]  fbx0, fbx1, fby0, fby1;  // the footprint's block columns and rows
  logic               two_cols, two_rows;
  logic [NumCand-1:0] cand_valid, present;
  logic [NumFp-1:0]   fp_miss;
  logic [NumAhead-1:0] ahead_miss;
  logic [TagW-1:0]    probe_blk;
  logic [SlotW-1:0]   probe_slot;

  assign fbx0 = x0_q[TexelW-1:2];
  assign fbx1 = x1_q[TexelW-1:2];
  assign fby0 = y0_q[TexelW-1:2];
  assign fby1 = y1_q[TexelW-1:2];

  // A footprint's second column / row of blocks exists when x1 (y1) is in the next block.
  assign two_cols      = fbx1 != fbx0;
  assign two_rows      = fby1 != fby0;
  assign cand_valid[0] = 1'b1;
  assign cand_valid[1] = two_cols;
  assign cand_valid[2] = two_rows;
  assign cand_valid[3] = two_cols && two_rows;
  assign cand_valid[4] = cfg_lookahead_i && nbx_in_q;
  assign cand_valid[5] = cfg_lookahead_i && nby_in_q;
  assign cand_valid[6] = cfg_lookahead_i && nbx_in_q && nby_in_q;

  always_comb begin
    present    = '0;
    probe_blk  = '0;
    probe_slot = '0;
    for (int k = 0; k < NumCand; k++) begin
      probe_blk  = cand_block(CandW'(k), fbx0, fbx1, fby0, fby1, bx_q, by_q, nbx_q, nby_q);
      probe_slot = slot_of(probe_blk);
      present[k] = entry_valid_q[probe_slot] && entry_tag_q[probe_slot] == probe_blk;
    end
  end

  assign fp_miss    = cand_valid[NumFp-1:0] & ~present[NumFp-1:0];
  assign ahead_miss = cand_valid[NumCand-1:NumFp] & ~present[NumCand-1:NumFp];

  // ---- Fill engine: the block being fetched ------------------------------------------------

  logic [TagW-1:0]    cur_blk;
  logic [SlotW-1:0]   cur_slot;
  logic [BlockW:0]    blocks_wide;  // ceil(width / 4)

  assign cur_blk     = cand_block(cur_q, fbx0, fbx1, fby0, fby1, bx_q, by_q, nbx_q, nby_q);
  assign cur_slot    = slot_of(cur_blk);
  assign blocks_wide = (BlockW + 1)'((cfg_width_i + SizeW'(3)) >> 2);

  // Memory address of a block: by * ceil(w/4) + bx (< 2^20 for any legal size).
  function automatic tmu_pkg::ccc_block_addr_t block_address(logic [TagW-1:0] blk,
                                                             logic [BlockW:0] wide);
    block_address = AddrW'(blk[TagW-1:BlockW]) * AddrW'(wide) + AddrW'(blk[BlockW-1:0]);
  endfunction

  // ---- Blend: the four texels of the footprint from their entries ---------------------------

  // Colour of texel idx (4*y + x) of an entry: decision bit 0 -> colour a, 1 -> colour b.
  function automatic tmu_pkg::rgb888_t pick(logic [15:0] bits, tmu_pkg::rgb888_t a,
                                           tmu_pkg::rgb888_t b, logic [3:0] idx);
    pick = bits[idx] ? b : a;
  endfunction

  // A texel's entry is {y[2], x[2]}: the low bits of its block coordinates.
  logic [SlotW-1:0]  s00, s10, s01, s11;
  tmu_pkg::rgb888_t  c00, c10, c01, c11, blend_rgb;

  assign s00 = {y0_q[2], x0_q[2]};
  assign s10 = {y0_q[2], x1_q[2]};
  assign s01 = {y1_q[2], x0_q[2]};
  assign s11 = {y1_q[2], x1_q[2]};
  assign c00 = pick(entry_bits_q[s00], entry_a_q[s00], entry_b_q[s00], {y0_q[1:0], x0_q[1:0]});
  assign c10 = pick(entry_bits_q[s10], entry_a_q[s10], entry_b_q[s10], {y0_q[1:0], x1_q[1:0]});
  assign c01 = pick(entry_bits_q[s01], entry_a_q[s01], entry_b_q[s01], {y1_q[1:0], x0_q[1:0]});
  assign c11 = pick(entry_bits_q[s11], entry_a_q[s11], entry_b_q[s11], {y1_q[1:0], x1_q[1:0]});

  // The bilinear interpolator (622), one blend per channel.
  for (genvar ch = 0; ch < RgbW / ChW; ch++) begin : gen_channel
    tmu_ccc_bilerp u_bilerp (
      .c00_i (c00[ch*ChW +: ChW]),
      .c10_i (c10[ch*ChW +: ChW]),
      .c01_i (c01[ch*ChW +: ChW]),
      .c11_i (c11[ch*ChW +: ChW]),
      .fx_i  (fx_q),
      .fy_i  (fy_q),
      .c_o   (blend_rgb[ch*ChW +: ChW])
    );
  end

  // ---- Control ------------------------------------------------------------------------------

  logic                 out_free;
  logic                 req_fire;
  logic                 blend_fire;
  logic                 start_fill;
  logic [NumCand-1:0]   fill_mask;
  logic [NumCand-1:0]   rest;
  logic                 clut_we, clut_re;
  tmu_pkg::clut_index_t clut_index;
  logic                 blk_we, entry_a_we, entry_fill;
  logic [2:0]           hits_inc, misses_inc, prefetches_inc;

  assign out_free = !out_valid_q || out_ready_i;
  assign req_fire = req_valid_i && req_ready_o;

  always_comb begin
    state_d         = state_q;
    miss_d          = miss_q;
    cur_d           = cur_q;
    mem_addr_d      = mem_addr_q;
    entry_valid_d   = entry_valid_q;
    req_ready_o     = 1'b0;
    clut_ready_o    = 1'b0;
    mem_req_valid_o = 1'b0;
    clut_we         = 1'b0;
    clut_re         = 1'b0;
    clut_index      = clut_addr_i;
    blk_we          = 1'b0;
    entry_a_we      = 1'b0;
    entry_fill      = 1'b0;
    blend_fire      = 1'b0;
    start_fill      = 1'b0;
    fill_mask       = '0;
    rest            = '0;
    hits_inc        = '0;
    misses_inc      = '0;
    prefetches_inc  = '0;

    unique case (state_q)
      StIdle: begin
        req_ready_o  = 1'b1;
        clut_ready_o = 1'b1;
        if (clut_valid_i) begin
          clut_we       = 1'b1;
          entry_valid_d = '0;  // the decoded colours are stale
        end
        if (req_valid_i) state_d = StLookup;
      end

      StLookup, StBlend: begin
        if (state_q == StLookup) begin
          hits_inc   = count_ones(cand_valid[NumFp-1:0] & present[NumFp-1:0]);
          misses_inc = count_ones(fp_miss);
        end
        if (state_q == StLookup && fp_miss != '0) begin
          start_fill = 1'b1;
          fill_mask  = NumCand'(fp_miss);
        end else if (out_free) begin
          blend_fire     = 1'b1;
          prefetches_inc = count_ones({1'b0, ahead_miss});
          if (ahead_miss != '0) begin
            start_fill = 1'b1;
            fill_mask  = {ahead_miss, NumFp'(0)};
          end else begin
            req_ready_o = 1'b1;  // done: the next request may be looked up at once
            state_d     = req_valid_i ? StLookup : StIdle;
          end
        end else begin
          state_d = StBlend;
        end
      end

      StMemReq: begin
        mem_req_valid_o = 1'b1;
        if (mem_req_ready_i) state_d = StMemWait;
      end

      StMemWait: begin
        if (mem_resp_valid_i) begin
          blk_we  = 1'b1;
          state_d = StClutA;
        end
      end

      StClutA: begin
        clut_re    = 1'b1;
        clut_index = blk_q[31:24];
        state_d    = StClutB;
      end

      StClutB: begin
        clut_re    = 1'b1;
        clut_index = blk_q[23:16];
        entry_a_we = 1'b1;
        state_d    = StFill;
      end

      StFill: begin
        entry_fill              = 1'b1;
        entry_valid_d[cur_slot] = 1'b1;
        rest                    = miss_q & ~(NumCand'(1) << cur_q);
        if (rest != '0) begin
          start_fill = 1'b1;
          fill_mask  = rest;
        end else if (cur_q < CandW'(NumFp)) begin
          state_d = StBlend;  // the footprint is complete
        end else begin
          state_d = StIdle;   // the lookahead is complete
        end
      end

      default: state_d = StIdle;
    endcase

    if (start_fill) begin
      miss_d     = fill_mask;
      cur_d      = first_set(fill_mask);
      mem_addr_d = block_address(
          cand_block(cur_d, fbx0, fbx1, fby0, fby1, bx_q, by_q, nbx_q, nby_q), blocks_wide);
      state_d    = StMemReq;
    end
  end

  assign out_valid_d  = blend_fire || (out_valid_q && !out_ready_i);
  assign hits_d       = hits_q + StatW'(hits_inc);
  assign misses_d     = misses_q + StatW'(misses_inc);
  assign prefetches_d = prefetches_q + StatW'(prefetches_inc);

  // ---- Flops --------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q       <= StIdle;
      entry_valid_q <= '0;
      out_valid_q   <= 1'b0;
      hits_q        <= '0;
      misses_q      <= '0;
      prefetches_q  <= '0;
    end else begin
      state_q       <= state_d;
      entry_valid_q <= entry_valid_d;
      out_valid_q   <= out_valid_d;
      hits_q        <= hits_d;
      misses_q      <= misses_d;
      prefetches_q  <= prefetches_d;
    end
  end

  // Data needs no reset: each register is written before the state that reads it.
  always_ff @(posedge clk_i) begin
    miss_q     <= miss_d;
    cur_q      <= cur_d;
    mem_addr_q <= mem_addr_d;
  end

  always_ff @(posedge clk_i) begin
    if (req_fire) begin
      x0_q     <= req_x0;
      x1_q     <= req_x1;
      y0_q     <= req_y0;
      y1_q     <= req_y1;
      fx_q     <= req_fx;
      fy_q     <= req_fy;
      bx_q     <= req_bx;
      by_q     <= req_by;
      nbx_q    <= req_nbx;
      nby_q    <= req_nby;
      nbx_in_q <= req_nbx_in;
      nby_in_q <= req_nby_in;
    end
  end

  always_ff @(posedge clk_i) begin
    if (blk_we) blk_q <= mem_resp_block_i;
  end

  // The CLUT: one port, written only while idle, read only while filling.
  always_ff @(posedge clk_i) begin
    if (clut_we) clut_q[clut_index] <= clut_rgb_i;
  end

  always_ff @(posedge clk_i) begin
    if (clut_re) clut_rdata_q <= clut_q[clut_index];
  end

  always_ff @(posedge clk_i) begin
    if (entry_a_we) entry_a_q[cur_slot] <= clut_rdata_q;
  end

  always_ff @(posedge clk_i) begin
    if (entry_fill) begin
      entry_b_q[cur_slot]    <= clut_rdata_q;
      entry_bits_q[cur_slot] <= blk_q[15:0];
      entry_tag_q[cur_slot]  <= cur_blk;
    end
  end

  always_ff @(posedge clk_i) begin
    if (blend_fire) out_rgb_q <= blend_rgb;
  end

  assign mem_req_addr_o    = mem_addr_q;
  assign out_valid_o       = out_valid_q;
  assign out_rgb_o         = out_rgb_q;
  assign stat_hits_o       = hits_q;
  assign stat_misses_o     = misses_q;
  assign stat_prefetches_o = prefetches_q;

  // ---- Assertions ---------------------------------------------------------------------------
  // They run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions and
  // defines SYNTHESIS.
`ifndef SYNTHESIS
  // Every fetched block is inside the texture.
  logic [BlockW:0] blocks_high;
  assign blocks_high = (BlockW + 1)'((cfg_height_i + SizeW'(3)) >> 2);
  property p_mem_addr_in_texture;
    @(posedge clk_i) disable iff (!rst_ni)
      mem_req_valid_o |-> (32'(mem_req_addr_o) < 32'(blocks_wide) * 32'(blocks_high));
  endproperty
  a_mem_addr_in_texture: assert property (p_mem_addr_in_texture);

  // The memory answers only the outstanding request (an assumption on the environment).
  property p_resp_expected;
    @(posedge clk_i) disable iff (!rst_ni) mem_resp_valid_i |-> (state_q == StMemWait);
  endproperty
  a_resp_expected: assert property (p_resp_expected);

  // The lookahead never evicts a block of the current footprint (000 §4: the neighbours of
  // the point's quadrant share no entry with its footprint unless they are the same block).
  logic [Entries-1:0] fp_slots;
  always_comb begin
    fp_slots = '0;
    for (int k = 0; k < NumFp; k++) begin
      if (cand_valid[k]) begin
        fp_slots[slot_of(cand_block(CandW'(k), fbx0, fbx1, fby0, fby1, bx_q, by_q, nbx_q,
                                    nby_q))] = 1'b1;
      end
    end
  end
  property p_lookahead_keeps_footprint;
    @(posedge clk_i) disable iff (!rst_ni)
      (state_q == StFill && cur_q >= CandW'(NumFp)) |-> !fp_slots[cur_slot];
  endproperty
  a_lookahead_keeps_footprint: assert property (p_lookahead_keeps_footprint);
`endif

endmodule
