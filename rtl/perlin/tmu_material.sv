/// The material unit (002 §4.2, Figs. 4.7-4.19; golden perlin::MaterialUnit in
/// golden/perlin/material_unit.hpp and golden/perlin/materials.hpp, the specification): a
/// register file and two colour tables behind a write port, and per sample (u, v, w) the three
/// stages shape -> fractal -> colour, so that the output is shade_material(u, v, w) on the
/// registers and tables written before the sample. One sample per clock with the pipelined
/// fractal unit, one per 4 clocks with the shared one (SharedFractal).
///
/// Write port (wr_*), the items of material_unit.hpp:
///   wr_op_i 0  register wr_reg_i (MaterialReg: 0 kind, 1 g_t, 2 g_v, 3 g_r, 4 g_w, 5 offset,
///              6 g_l, 7 cutoff, 8 pw, 9 ph, 10 mortar_w, 11 mortar_h) <= wr_value_i, a value
///              outside the register's range stored as its nearest limit (kind at most 5, pw
///              and ph 1..20, a mortar at most 2^(p-1) - 1, also when pw or ph shrink); ids
///              12..15 are ignored. The registers reset to golden's MaterialRegs defaults.
///   wr_op_i 1  colour table wr_table_i (0 main, 1 mortar) entry wr_index_i <= wr_rgb_i; an
///              index beyond 127 is ignored. The tables have no reset: load every entry a
///              sample will read.
/// Ordering: a sample reads the registers in the stages it passes and the tables in its last
/// one, so a write waits until every sample accepted before it has left the colour stage:
/// wr_ready_o is high when no sample is in flight and none is presented (in_valid_i low; a
/// sample presented together with a write goes first). Writes back to back take one clock
/// each; a write after samples waits for them (at most the latency). Every sample then sees
/// exactly the writes accepted before it, as MaterialUnit applies them.
///
/// Stages (each a register with a valid bit; a stage loads when it is empty or hands its
/// sample on, so bubbles close up):
///   S1 shape   the fractal unit's coordinates: cloud (2u, v, w) (u shifted left, wrapped to 24
///              bits: the noise reads only the low 24 bits), fire (u, e^-v, w) with e^-v from
///              the 512-entry table (tmu_material_fire) at k = clamp(floor(v 32), 0, 511), the
///              others (u, v, w). Alongside, the index terms of the coordinates: u^2 + v^2 mod
///              2^39 (wood), w g_w (wood) or v g_v (marble) mod 2^27 on one multiplier (bits
///              26:12 are the term floored to 8 fraction bits mod 2^15), and the brick test
///   S2 base    the index value before the fractal term, mod 2^15: wood
///              ((u^2 + v^2) g_r >> 24) + (w g_w >> 12) (bits 38:24 of the product mod 2^39),
///              marble v g_v >> 12, else 0
///   fractal    tmu_fractal_pipelined (latency 8) or tmu_fractal_shared (latency 12); the base
///              and the brick bit wait in a FIFO (FifoDepth entries) and meet the sums again
///   C1 product one 17 x 17 multiplier for the material's product, exact: T g_t (marble, wood,
///              brick), F g_t (fire), |F| g_l (fog; F (-g_l) for F < 0, -g_l kept in a
///              register) or max(F, 0) g_l (cloud); its bits 32:14; cloud's F > cutoff
///   C2 colour  T g_t >> 14 added to the base mod 2^15 (marble, wood, brick); fire
///              clamp((F g_t >>> 14) + offset, 0, 2^15 - 1); the entry is bits 14:8; brick
///              picks the mortar table outside a brick; the gases' level min(255, m g_l >> 22)
///              (cloud's 0 unless F > cutoff)
///   out        the table read (main or mortar at the entry) or the gases' grey / r = g, b = 255
/// Latency 13 cycles with the pipelined fractal unit (a sample accepted at an edge is on the
/// output 12 edges later when nothing stalls), 17 with the shared one.
///
/// Example (marble, g_t = 0, g_v = 1.0 = 256): (u, v, w) = (0, 127.5, 0) = (0, 0x07F800, 0):
/// v g_v = 0x7F80000, bits 26:12 = 0x7F80, T g_t = 0: entry 127, out_rgb_o = main[127]; at
/// v = 128.0 = 0x080000 the index 0x8000 wraps to 0: main[0].
module tmu_material #(
  /// 1: the fractal sums on one noise unit for the four octaves (tmu_fractal_shared, 4 clocks
  /// per sample); 0: four pipelined units (tmu_fractal_pipelined, one sample per clock).
  parameter int unsigned SharedFractal = 0
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,

  /// Write port: a register (wr_op_i 0) or a colour-table entry (wr_op_i 1).
  input  logic                  wr_valid_i,
  output logic                  wr_ready_o,
  input  logic                  wr_op_i,
  input  logic [3:0]            wr_reg_i,
  input  logic [15:0]           wr_value_i,
  input  logic                  wr_table_i,
  input  logic [7:0]            wr_index_i,
  input  tmu_pkg::rgb888_t      wr_rgb_i,

  /// The solid coordinates of a sample, SQ12.12.
  input  logic                  in_valid_i,
  output logic                  in_ready_o,
  input  tmu_pkg::solid_coord_t in_u_i,
  input  tmu_pkg::solid_coord_t in_v_i,
  input  tmu_pkg::solid_coord_t in_w_i,

  /// The colour, RGB888.
  output logic                  out_valid_o,
  input  logic                  out_ready_i,
  output tmu_pkg::rgb888_t      out_rgb_o
);

  localparam int unsigned CW        = tmu_pkg::SolidCoordW;    // 24
  localparam int unsigned SW        = tmu_pkg::FractalValueW;  // 16, SQ2.14
  localparam int unsigned IW        = 15;                      // index value, IQ7.8 mod 2^15
  localparam int unsigned FireW     = 20;                      // fire's index before the clamp
  localparam int unsigned Entries   = 128;
  localparam int unsigned FifoDepth = SharedFractal != 0 ? 4 : 8;   // samples in the fractal unit
  localparam int unsigned PtrW      = $clog2(FifoDepth);

  if (CW != 24 || tmu_pkg::SolidCoordFrac != 12 || SW != 16 || tmu_pkg::Rgb888W != 24)
  begin : gen_check_formats
    $error("tmu_material: built for SQ12.12 coordinates, SQ2.14 sums and RGB888");
  end

  // MaterialKind.
  localparam logic [2:0] Marble = 3'd0, Wood = 3'd1, Brick = 3'd2, Fog = 3'd3, Cloud = 3'd4,
                         Fire = 3'd5;

  // ---- Registers (MaterialRegs), reset to golden's defaults ---------------------------------

  logic [2:0]  kind_q;
  logic [15:0] gt_q, gv_q, gr_q, gw_q, offset_q, gl_q, cutoff_q;  // g_w, offset, cutoff signed
  logic [4:0]  pw_q, ph_q;                                          // 1..20
  logic [15:0] mw_q, mh_q;                                          // <= 2^(p-1) - 1
  logic [16:0] gl_neg_q;  // -g_l, signed: fog's |F| g_l = F (-g_l) for F < 0, no negation of F

  // The largest mortar of a period 2^p: 2^(p-1) - 1 (up to 2^19 - 1).
  function automatic logic [19:0] mortar_limit(input logic [4:0] p);
    mortar_limit = (20'(1) << (p - 5'd1)) - 20'd1;
  endfunction
  // min(value, 2^(p-1) - 1): the limit is below value only when it fits 16 bits.
  function automatic logic [15:0] mortar_sat(input logic [15:0] value, input logic [4:0] p);
    logic [19:0] lim;
    lim        = mortar_limit(p);
    mortar_sat = 20'(value) > lim ? lim[15:0] : value;
  endfunction
  // clamp(value, 1, 20).
  function automatic logic [4:0] period_sat(input logic [15:0] value);
    period_sat = value == '0 ? 5'd1 : (value > 16'd20 ? 5'd20 : value[4:0]);
  endfunction

  logic wr_fire, reg_write, table_write;
  logic [4:0] new_p;

  assign wr_fire     = wr_valid_i && wr_ready_o;
  assign reg_write   = wr_fire && !wr_op_i;
  assign table_write = wr_fire && wr_op_i && !wr_index_i[7];  // beyond 127: ignored
  assign new_p       = period_sat(wr_value_i);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      kind_q   <= Marble;
      gt_q     <= 16'(32 << 8);
      gv_q     <= 16'(8 << 8);
      gr_q     <= 16'(16 << 8);
      gw_q     <= 16'(2 << 8);
      offset_q <= '0;
      gl_q     <= 16'(255 << 8);
      gl_neg_q <= -17'(255 << 8);
      cutoff_q <= '0;
      pw_q     <= 5'd12;
      ph_q     <= 5'd11;
      mw_q     <= 16'd205;
      mh_q     <= 16'd205;
    end else if (reg_write) begin
      unique case (wr_reg_i)
        4'd0: kind_q <= wr_value_i > 16'(Fire) ? Fire : wr_value_i[2:0];
        4'd1: gt_q <= wr_value_i;
        4'd2: gv_q <= wr_value_i;
        4'd3: gr_q <= wr_value_i;
        4'd4: gw_q <= wr_value_i;
        4'd5: offset_q <= wr_value_i;
        4'd6: begin
          gl_q     <= wr_value_i;
          gl_neg_q <= -{1'b0, wr_value_i};
        end
        4'd7: cutoff_q <= wr_value_i;
        4'd8: begin
          pw_q <= new_p;
          mw_q <= mortar_sat(mw_q, new_p);
        end
        4'd9: begin
          ph_q <= new_p;
          mh_q <= mortar_sat(mh_q, new_p);
        end
        4'd10: mw_q <= mortar_sat(wr_value_i, pw_q);
        4'd11: mh_q <= mortar_sat(wr_value_i, ph_q);
        default: ;  // no such register: ignored
      endcase
    end
  end

  // ---- Colour tables: flops, one write port, an asynchronous read in the output stage ------

  tmu_pkg::rgb888_t main_q [Entries];
  tmu_pkg::rgb888_t mortar_q [Entries];

  always_ff @(posedge clk_i) begin
    if (table_write && !wr_table_i) main_q[wr_index_i[6:0]] <= wr_rgb_i;
    if (table_write && wr_table_i) mortar_q[wr_index_i[6:0]] <= wr_rgb_i;
  end

  // ---- Handshake ------------------------------------------------------------------------------

  logic s1_valid_q, s2_valid_q, c1_valid_q, c2_valid_q, out_valid_q;
  logic s1_adv, s2_adv, s2_fire, c1_adv, c2_adv, out_load;
  logic frac_in_ready, frac_out_valid;
  logic fifo_room, fifo_empty, fifo_pop;

  assign out_load   = !out_valid_q || out_ready_i;
  assign c2_adv     = !c2_valid_q || out_load;
  assign c1_adv     = !c1_valid_q || c2_adv;
  assign fifo_pop   = frac_out_valid && c1_adv;  // C1 takes the fractal unit's output
  assign s2_fire    = s2_valid_q && fifo_room && frac_in_ready;
  assign s2_adv     = !s2_valid_q || s2_fire;
  assign s1_adv     = !s1_valid_q || s2_adv;
  assign in_ready_o = s1_adv;
  // Writes wait for every sample before them to leave C2 (the fractal unit holds exactly the
  // samples whose entries are in the FIFO).
  assign wr_ready_o = !s1_valid_q && !s2_valid_q && fifo_empty && !c1_valid_q && !c2_valid_q &&
                      !in_valid_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_valid_q  <= 1'b0;
      s2_valid_q  <= 1'b0;
      c1_valid_q  <= 1'b0;
      c2_valid_q  <= 1'b0;
      out_valid_q <= 1'b0;
    end else begin
      if (s1_adv) s1_valid_q <= in_valid_i;
      if (s2_adv) s2_valid_q <= s1_valid_q;
      if (c1_adv) c1_valid_q <= frac_out_valid;
      if (c2_adv) c2_valid_q <= c1_valid_q;
      if (out_load) out_valid_q <= c2_valid_q;
    end
  end

  // ---- -> S1: shape, the coordinates' index terms, the brick test ---------------------------

  // Fire: k = floor(v 32) = v >> 7 clamped to 0..511: v < 0 reads entry 0, v >= 16.0 entry 511.
  logic [8:0]  fire_k;
  logic [12:0] fire_e;  // e^-v, UQ1.12
  assign fire_k = in_v_i[CW-1] ? 9'd0 : (|in_v_i[CW-2:16] ? 9'd511 : in_v_i[15:7]);
  tmu_material_fire u_fire (.in_k_i(fire_k), .out_entry_o(fire_e));

  tmu_pkg::solid_coord_t shaped_u, shaped_v;
  assign shaped_u = kind_q == Cloud ? {in_u_i[CW-2:0], 1'b0} : in_u_i;
  assign shaped_v = kind_q == Fire ? CW'(fire_e) : in_v_i;

  // Products mod 2^39 and 2^27 on sign-extended operands: the low bits of a two's complement
  // product are those of the operands' low bits. Marble's v g_v and wood's w g_w share one
  // multiplier (a material needs one of them).
  logic [38:0] sq;                    // u^2 + v^2 mod 2^39
  logic [26:0] term_a, term_b, term;  // marble v g_v, else w g_w, mod 2^27
  assign sq     = 39'(in_u_i) * 39'(in_u_i) + 39'(in_v_i) * 39'(in_v_i);
  assign term_a = kind_q == Marble ? 27'(in_v_i) : 27'(in_w_i);
  assign term_b = kind_q == Marble ? 27'(gv_q) : 27'($signed(gw_q));
  assign term   = term_a * term_b;

  // Brick: row = v >> ph; an even row is shifted by half a period; u_r = u' mod 2^pw,
  // v_r = v mod 2^ph; brick when M_W < u_r < 2^pw - M_W and M_H < v_r < 2^ph - M_H.
  logic        row_bit, even_row, in_brick;
  logic [20:0] u_shifted, ur, vr, pw_period, ph_period;
  assign row_bit   = in_v_i[ph_q];
  assign even_row  = !row_bit;
  assign pw_period = 21'(1) << pw_q;
  assign ph_period = 21'(1) << ph_q;
  assign u_shifted = in_u_i[20:0] + (even_row ? pw_period >> 1 : '0);
  assign ur        = u_shifted & (pw_period - 21'd1);
  assign vr        = in_v_i[20:0] & (ph_period - 21'd1);
  assign in_brick  = 21'(mw_q) < ur && ur < pw_period - 21'(mw_q) &&
                     21'(mh_q) < vr && vr < ph_period - 21'(mh_q);

  // Data registers: only read while their stage is valid, no reset.
  tmu_pkg::solid_coord_t s1_u_q, s1_v_q, s1_w_q;  // shaped
  logic [38:0]           s1_sq_q;
  logic [IW-1:0]         s1_term_q;
  logic                  s1_brick_q;

  always_ff @(posedge clk_i) begin
    if (s1_adv && in_valid_i) begin
      s1_u_q     <= shaped_u;
      s1_v_q     <= shaped_v;
      s1_w_q     <= in_w_i;
      s1_sq_q    <= sq;
      s1_term_q  <= term[26:12];
      s1_brick_q <= in_brick;
    end
  end

  logic unused_s1;
  assign unused_s1 = ^term[11:0];

  // ---- S1 -> S2: the base of the index ----------------------------------------------------

  logic [38:0]   rings_product;  // (u^2 + v^2) g_r mod 2^39
  logic [IW-1:0] base;
  assign rings_product = s1_sq_q * 39'(gr_q);
  always_comb begin
    unique case (kind_q)
      Wood:    base = rings_product[38:24] + s1_term_q;
      Marble:  base = s1_term_q;
      default: base = '0;
    endcase
  end

  tmu_pkg::solid_coord_t s2_u_q, s2_v_q, s2_w_q;
  logic [IW-1:0]         s2_base_q;
  logic                  s2_brick_q;

  always_ff @(posedge clk_i) begin
    if (s2_adv && s1_valid_q) begin
      s2_u_q     <= s1_u_q;
      s2_v_q     <= s1_v_q;
      s2_w_q     <= s1_w_q;
      s2_base_q  <= base;
      s2_brick_q <= s1_brick_q;
    end
  end

  logic unused_rings;
  assign unused_rings = ^rings_product[23:0];

  // ---- The fractal unit, and the FIFO of the samples inside it -----------------------------

  logic [SW-1:0] frac_sum, frac_turb;

  if (SharedFractal != 0) begin : gen_shared
    tmu_fractal_shared u_fractal (
      .clk_i            (clk_i),
      .rst_ni           (rst_ni),
      .in_valid_i       (s2_valid_q && fifo_room),
      .in_ready_o       (frac_in_ready),
      .in_u_i           (s2_u_q),
      .in_v_i           (s2_v_q),
      .in_w_i           (s2_w_q),
      .out_valid_o      (frac_out_valid),
      .out_ready_i      (c1_adv),
      .out_sum_o        (frac_sum),
      .out_turbulence_o (frac_turb)
    );
  end else begin : gen_pipelined
    tmu_fractal_pipelined u_fractal (
      .clk_i            (clk_i),
      .rst_ni           (rst_ni),
      .in_valid_i       (s2_valid_q && fifo_room),
      .in_ready_o       (frac_in_ready),
      .in_u_i           (s2_u_q),
      .in_v_i           (s2_v_q),
      .in_w_i           (s2_w_q),
      .out_valid_o      (frac_out_valid),
      .out_ready_i      (c1_adv),
      .out_sum_o        (frac_sum),
      .out_turbulence_o (frac_turb)
    );
  end

  // The base and the brick bit of each sample in the fractal unit, in order: pushed when the
  // unit takes the sample, popped when C1 takes its sums.
  logic [IW:0]   fifo_q [FifoDepth];
  logic [PtrW-1:0] fifo_rd_q, fifo_wr_q;
  logic [PtrW:0] fifo_count_q;
  logic [IW:0]   fifo_head;

  assign fifo_empty = fifo_count_q == '0;
  assign fifo_room  = fifo_count_q != (PtrW + 1)'(FifoDepth) || fifo_pop;
  assign fifo_head  = fifo_q[fifo_rd_q];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      fifo_rd_q    <= '0;
      fifo_wr_q    <= '0;
      fifo_count_q <= '0;
    end else begin
      if (s2_fire) fifo_wr_q <= fifo_wr_q + 1'b1;
      if (fifo_pop) fifo_rd_q <= fifo_rd_q + 1'b1;
      fifo_count_q <= fifo_count_q + (PtrW + 1)'(s2_fire) - (PtrW + 1)'(fifo_pop);
    end
  end

  always_ff @(posedge clk_i) begin
    if (s2_fire) fifo_q[fifo_wr_q] <= {s2_brick_q, s2_base_q};
  end

  // ---- -> C1: the product --------------------------------------------------------------

  logic [IW-1:0] head_base;
  logic          head_brick;
  assign {head_brick, head_base} = fifo_head;

  // One 17 x 17 multiplier for the material's product, exact: T g_t (marble, wood, brick),
  // F g_t (fire), |F| g_l (fog: F (-g_l) for F < 0), max(F, 0) g_l (cloud: where F <= 0 the
  // floored product is <= 0, level 0).
  logic signed [SW:0]     mul_a, mul_b;
  logic signed [2*SW+1:0] product;
  always_comb begin
    unique case (kind_q)
      Fire, Fog: mul_a = {frac_sum[SW-1], frac_sum};
      Cloud:     mul_a = frac_sum[SW-1] ? '0 : {1'b0, frac_sum};
      default:   mul_a = {1'b0, frac_turb};
    endcase
    unique case (kind_q)
      Fog:     mul_b = frac_sum[SW-1] ? gl_neg_q : {1'b0, gl_q};
      Cloud:   mul_b = {1'b0, gl_q};
      default: mul_b = {1'b0, gt_q};
    endcase
  end
  assign product = mul_a * mul_b;

  // Bits 32:14 of the product are all the colour stage reads: |F g_t| and m g_l are below 2^31.
  logic [18:0]   c1_product_q;
  logic [IW-1:0] c1_base_q;
  logic          c1_mortar_q, c1_above_q;

  always_ff @(posedge clk_i) begin
    if (fifo_pop) begin
      c1_product_q <= product[32:14];
      c1_base_q    <= head_base;
      c1_mortar_q  <= kind_q == Brick && !head_brick;
      c1_above_q   <= $signed(frac_sum) > $signed(cutoff_q);  // cloud: F > cutoff
    end
  end

  logic unused_product;
  assign unused_product = ^{product[2*SW+1:33], product[13:0]};

  // ---- C1 -> C2: the entry, the gases' level ------------------------------------------------

  // Marble, wood, brick: base + (T g_t >> 14), mod 2^15 (the 128 entries wrap).
  logic [IW:0]   index_sum;
  logic [IW-1:0] index_mod;
  assign index_sum = {1'b0, c1_base_q} + {1'b0, c1_product_q[IW-1:0]};
  assign index_mod = index_sum[IW-1:0];

  // Fire: (F g_t >>> 14) + offset, clamped to 0 .. 2^15 - 1 (no wrap).
  logic signed [FireW-1:0] fire_sum;
  logic [IW-1:0]           fire_index;
  assign fire_sum   = FireW'($signed(c1_product_q)) + FireW'($signed(offset_q));
  assign fire_index = fire_sum < 0 ? '0 : (fire_sum > $signed(FireW'(2**IW - 1)) ? '1 : fire_sum[IW-1:0]);

  // Fog and cloud: min(255, m g_l >> 22); cloud's level is 0 unless F > cutoff.
  logic [7:0] gas_level;
  assign gas_level = |c1_product_q[17:16] ? 8'd255 : c1_product_q[15:8];

  logic [6:0] c2_entry_q;
  logic       c2_mortar_q, c2_gas_q, c2_cloud_q;
  logic [7:0] c2_level_q;

  always_ff @(posedge clk_i) begin
    if (c2_adv && c1_valid_q) begin
      c2_entry_q  <= kind_q == Fire ? fire_index[IW-1:8] : index_mod[IW-1:8];
      c2_mortar_q <= c1_mortar_q;
      c2_gas_q    <= kind_q == Fog || kind_q == Cloud;
      c2_cloud_q  <= kind_q == Cloud;
      c2_level_q  <= kind_q == Cloud && !c1_above_q ? '0 : gas_level;
    end
  end

  logic unused_c2;
  assign unused_c2 = ^{index_sum[IW], index_mod[7:0], fire_index[7:0], c1_product_q[7:0]};

  // ---- C2 -> out: the table read ------------------------------------------------------------

  tmu_pkg::rgb888_t colour, out_rgb_q;
  always_comb begin
    if (c2_gas_q) colour = {c2_level_q, c2_level_q, c2_cloud_q ? 8'hFF : c2_level_q};
    else if (c2_mortar_q) colour = mortar_q[c2_entry_q];
    else colour = main_q[c2_entry_q];
  end

  always_ff @(posedge clk_i) begin
    if (out_load && c2_valid_q) out_rgb_q <= colour;
  end

  assign out_valid_o = out_valid_q;
  assign out_rgb_o   = out_rgb_q;

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // Every output of the fractal unit has its FIFO entry; the FIFO never overflows.
  a_fifo_entry: assert property (@(posedge clk_i) disable iff (!rst_ni)
      frac_out_valid |-> !fifo_empty);
  a_fifo_bound: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fifo_count_q <= (PtrW + 1)'(FifoDepth));
  // The registers stay in their ranges.
  a_reg_ranges: assert property (@(posedge clk_i) disable iff (!rst_ni)
      kind_q <= Fire && pw_q >= 5'd1 && pw_q <= 5'd20 && ph_q >= 5'd1 && ph_q <= 5'd20 &&
      20'(mw_q) <= mortar_limit(pw_q) && 20'(mh_q) <= mortar_limit(ph_q));
`endif

endmodule
