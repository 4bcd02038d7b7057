/// The normal encoder's ratio divider (001 §4.1, eq. 15-16; golden deflect::divide_ratio in
/// golden/deflect/normal_encoder.hpp, the specification): t = num / den in UQ1.16 for
/// num <= den, by a seed table and one Newton-Raphson step. Four register stages; the encoder
/// owns the pipeline control and gives each stage its load enable.
///
///   A  normalise  s = leading zeros of den; d = (den << s) >> 16 (UQ1.15, [2^15, 2^16)),
///                 n = (num << s) >> 16; r0 = SEED[i], i the S bits of d below its leading
///                 one, SEED[i] = round(2^(16+S) / (2^(S+1) + 2i + 1)) (UQ1.15)
///   B  error      e = 2^31 - d r0 (UQ1.30: 2 - d r0)
///   C  step       r1 = (r0 e) >> 29 (UQ1.16, truncated)
///   D  quotient   t = min((n r1) >> 15, 2^16)
///
/// Widths (every d in [2^15, 2^16) enumerated for S = 2..12): r0 < 2^15, d r0 < 2^31,
/// 2^30 - 2^27 < e < 2^31, r1 < 2^16 (Newton-Raphson from below never exceeds 1/d).
/// den = 0 (then num = 0): d = n = 0 and t = 0 whatever r1 is, as golden's special case.
///
/// Example (S = 7): num = 1, den = 3: s = 30, d = 0xC000 (1.5), n = 0x4000 (0.5), i = 64,
/// r0 = round(2^23 / 385) = 21789 (0.66495), e = 2^31 - 0xC000 * 21789 = 0x402A_4000,
/// r1 = 43690 (0.66666), t = (0x4000 * 43690) >> 15 = 21845 (1/3 in UQ1.16, truncated).
module tmu_normal_divider #(
  /// S: index bits of the reciprocal seed table, 2..12.
  parameter int unsigned SeedBits = 7
) (
  input  logic        clk_i,

  /// Load enables of stages A, B, C, D: the stage takes its inputs at this edge.
  input  logic [3:0]  load_i,
  /// Operands (stage A's inputs), num <= den (the encoder asserts it).
  input  logic [31:0] num_i,
  input  logic [31:0] den_i,
  /// t = num / den in UQ1.16, 0 .. 2^16 (stage D).
  output logic [16:0] t_o
);

  localparam int unsigned S = SeedBits;

  if (S < 2 || S > 12) begin : gen_check
    $error("tmu_normal_divider: SeedBits 2..12");
  end

  // golden seed_entry in integers: round(2^(16+S) / den) = (2^(17+S) + den) / (2 den).
  function automatic logic [14:0] seed_entry(input int unsigned index);
    int unsigned den;
    den = (1 << (S + 1)) + 2 * index + 1;
    seed_entry = 15'(((1 << (17 + S)) + den) / (2 * den));
  endfunction

  // The table, one constant per entry (two loops: Verilator unrolls at most 1024 iterations).
  localparam int unsigned SeedEntries = 1 << S;
  localparam int unsigned SeedInner   = SeedEntries > 512 ? 512 : SeedEntries;
  logic [SeedEntries*15-1:0] seed_bits;
  for (genvar hi = 0; hi < SeedEntries / SeedInner; hi++) begin : gen_seed_block
    for (genvar lo = 0; lo < SeedInner; lo++) begin : gen_seed
      localparam int unsigned Index = hi * SeedInner + lo;
      localparam logic [14:0] Entry = seed_entry(Index);
      assign seed_bits[Index*15 +: 15] = Entry;
    end
  end

  // ---- A: normalise, seed ---------------------------------------------------------------------

  logic [4:0]   lead_zeros;
  logic [15:0]  d, n;
  logic [S-1:0] seed_index;

  // Leading zeros of den (0 for den = 0: d = n = 0 then).
  always_comb begin
    lead_zeros = '0;
    for (int b = 0; b < 32; b++) begin
      if (den_i[b]) lead_zeros = 5'(31 - b);
    end
  end
  // The top 16 bits of the operands shifted by den's leading zeros (num <= den: nothing of
  // num is shifted out).
  assign d          = 16'((den_i << lead_zeros) >> 16);
  assign n          = 16'((num_i << lead_zeros) >> 16);
  assign seed_index = d[14 -: S];

  logic [15:0] a_d_q, a_n_q;
  logic [14:0] a_r0_q;

  // ---- B: e = 2 - d r0 ------------------------------------------------------------------------

  logic [30:0] error;
  // d r0 < 2^31 and e < 2^31 (den = 0: e = 2^31 wraps to 0, harmless as n = 0).
  assign error = 31'(32'h8000_0000 - 32'(a_d_q) * 32'(a_r0_q));

  logic [15:0] b_n_q;
  logic [14:0] b_r0_q;
  logic [30:0] b_e_q;

  // ---- C: r1 = r0 e, truncated to UQ1.16 -------------------------------------------------------

  logic [45:0] nr_product;
  logic [15:0] r1;
  assign nr_product = 46'(b_r0_q) * 46'(b_e_q);
  assign r1         = 16'(nr_product >> 29);

  logic [15:0] c_n_q, c_r1_q;

  // ---- D: t = n r1, saturated at 1.0 -----------------------------------------------------------

  logic [31:0] quotient_product;
  logic [16:0] quotient;
  assign quotient_product = 32'(c_n_q) * 32'(c_r1_q);
  assign quotient = 17'(quotient_product >> 15);  // < 2^17: n, r1 < 2^16

  logic [16:0] d_t_q;
  assign t_o = d_t_q;

  // Data registers only: the encoder's valid bits say which hold a ratio.
  always_ff @(posedge clk_i) begin
    if (load_i[0]) begin
      a_d_q  <= d;
      a_n_q  <= n;
      a_r0_q <= seed_bits[32'(seed_index)*15 +: 15];
    end
    if (load_i[1]) begin
      b_n_q  <= a_n_q;
      b_r0_q <= a_r0_q;
      b_e_q  <= error;
    end
    if (load_i[2]) begin
      c_n_q  <= b_n_q;
      c_r1_q <= r1;
    end
    if (load_i[3]) begin
      d_t_q <= quotient > 17'h1_0000 ? 17'h1_0000 : quotient;
    end
  end

endmodule
