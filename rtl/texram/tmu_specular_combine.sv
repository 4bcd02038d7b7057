/// The specular combine (000 §7 eq. 6, §8 eq. 7; golden texram::specular_combine in
/// golden/texram/specular_combine.hpp, the specification):
///
///   C = (C_d | I_d) + R . (E | I_s)
///
/// with D the diffusely shaded texture colour, E the environment-map or specular shading-map
/// sample and R the reflectance (the register k_s or the reflectance map's sample), all
/// RGBA8888 (R 31:24, G 23:16, B 15:8, A 7:0). Per colour channel c of R, G, B:
///
///   C_c = min(255, D_c + round(E_c R_c / 255))      (tmu_mul255)
///
/// and C's alpha is D's alpha (reflections add light, not coverage); E's and R's alphas are
/// not used. One colour per clock.
///
/// Pipeline. Each stage is a register with a valid bit; the whole pipeline advances when the
/// output register is empty or being taken, and stalls otherwise:
///   S1 product    per channel round(E_c R_c / 255) (an 8 x 8 product and the /255 rounding),
///                 D's colour channels and alpha
///   S2 sum        per channel D_c + product, saturated at 255; alpha: out_colour_o
/// A colour accepted at an edge is on the output at the next edge when nothing stalls
/// (latency 2 cycles).
///
/// Example: D = 0xF0804020, E = 0x80FF40FF, R = 0x40FFFF00: R: 240 + round(128 * 64 / 255)
/// = 240 + 32 = 272, saturated to 255; G: 128 + 255 = 383 -> 255; B: 64 + 64 = 128; alpha 0x20.
/// Output 0xFFFF8020.
module tmu_specular_combine (
  input  logic               clk_i,
  input  logic               rst_ni,

  /// D, E and R.
  input  logic               in_valid_i,
  output logic               in_ready_o,
  input  tmu_pkg::rgba8888_t in_diffuse_i,
  input  tmu_pkg::rgba8888_t in_specular_i,
  input  tmu_pkg::rgba8888_t in_reflectance_i,

  /// C.
  output logic               out_valid_o,
  input  logic               out_ready_i,
  output tmu_pkg::rgba8888_t out_colour_o
);

  localparam int unsigned ChW       = tmu_pkg::ChannelW;                 // 8
  localparam int unsigned Chs       = tmu_pkg::Rgba8888W / ChW;          // 4: A at 0, B, G, R
  localparam int unsigned NumStages = 2;

  if (ChW != 8 || Chs != 4) begin : gen_check_formats
    $error("tmu_specular_combine: built for RGBA8888");
  end

  // ---- Pipeline control: tmu_pipe_ctrl ------------------------------------------------------

  // valid[j]: stage j holds a colour; load[j]: stage j takes stage j - 1's at this edge.
  // The stages load on load[j]; of the valids only an assertion reads one (valid[1]).
  // verilator lint_off UNUSEDSIGNAL
  logic [NumStages:1] valid, load;
  // verilator lint_on UNUSEDSIGNAL

  tmu_pipe_ctrl #(.NumStages(NumStages)) u_pipe_ctrl (.clk_i, .rst_ni, .in_valid_i, .in_ready_o,
    .out_valid_o, .out_ready_i, .valid_o(valid), .load_o(load));

  // ---- -> S1: the products ------------------------------------------------------------------

  // Channel ch (1 B, 2 G, 3 R) at [ch * ChW +: ChW]; the alpha (ch = 0) has no product.
  logic [Chs*ChW-1:ChW] product;

  for (genvar ch = 1; ch < Chs; ch++) begin : gen_product
    tmu_mul255 u_mul255 (
      .t_i (in_specular_i[ch*ChW +: ChW]),
      .m_i (in_reflectance_i[ch*ChW +: ChW]),
      .p_o (product[ch*ChW +: ChW])
    );
  end

  // E's and R's alphas are not part of the rule.
  logic unused_alphas;
  assign unused_alphas = ^{in_specular_i[ChW-1:0], in_reflectance_i[ChW-1:0]};

  logic [Chs*ChW-1:ChW] s1_diffuse_q, s1_product_q;
  tmu_pkg::channel_t    s1_alpha_q;

  // ---- S1 -> S2: the saturating sums --------------------------------------------------------

  tmu_pkg::rgba8888_t colour;
  assign colour[ChW-1:0] = s1_alpha_q;

  for (genvar ch = 1; ch < Chs; ch++) begin : gen_sum
    logic [ChW:0] sum;  // at most 255 + 255
    assign sum = (ChW + 1)'(s1_diffuse_q[ch*ChW +: ChW])
               + (ChW + 1)'(s1_product_q[ch*ChW +: ChW]);
    assign colour[ch*ChW +: ChW] = sum[ChW] ? '1 : sum[ChW-1:0];

`ifndef SYNTHESIS
    // Reflections only add light: no channel of C is below D's.
    a_no_darkening: assert property (@(posedge clk_i) disable iff (!rst_ni)
        valid[1] |-> colour[ch*ChW +: ChW] >= s1_diffuse_q[ch*ChW +: ChW]);
`endif
  end

  tmu_pkg::rgba8888_t s2_colour_q;

  assign out_colour_o = s2_colour_q;

  // ---- Data registers: only read while their stage is valid, no reset --------------------------

  always_ff @(posedge clk_i) begin
    if (load[1]) begin
      s1_diffuse_q <= in_diffuse_i[Chs*ChW-1:ChW];
      s1_product_q <= product;
      s1_alpha_q   <= in_diffuse_i[ChW-1:0];
    end
    if (load[2]) s2_colour_q <= colour;
  end

endmodule
