/// The footprint setup (000 §10, eq. 19-22; golden footprint::plan in
/// golden/footprint/footprint.hpp, the specification): from a fragment's derivative vectors
/// r1 = d(u,v)/dx and r2 = d(u,v)/dy, the number of probes N = 2^k, the marching direction
/// (the longer vector) and the probes' lambda.
///
/// Arithmetic, with D = DerivBits, T = TableBits, F = LogFracBits, G = F + 1:
///   sh = max(0, bitlen(max |component|) - D); a = sign(c) (|c| >> sh) (toward zero), |a| < 2^D
///   s1 = |a1|^2, s2 = |a2|^2, area = |a1 x a2| (exact, < 2^(2D+1)); r2 is the longer when
///   s2 > s1; smax, smin the larger and the smaller square
///   lg: tmu_footprint_log2 (leading one + table) of smax and of the second operand, area
///   (q rule heights) or smin (sides)
///   in G fraction bits, offset = (2 sh - 16) 2^F:
///     log2 |r_max| = lg(smax) + offset
///     heights: log2 q = 2 lg(area) - lg(smax) + offset, rho = 2 (lg(smax) - lg(area))
///     sides:   log2 q = lg(smin) + offset,               rho = lg(smax) - lg(smin)
///   k = min(kmax, (rho + 2^(G-1)) >> G), kmax when the second operand is 0 (unbounded);
///   then probes at least 2^-SpacingLog2 = a quarter texel apart: k <= max(0, floor(log2
///   |r_max|) + SpacingLog2), exactly from the leading one e of smax: floor(log2 |r_max|) =
///   (e + 2 sh - 16) >> 1 (floor), so the cap is max(0, (e + 2 sh - 16 + 2 SpacingLog2) >> 1)
///   (a footprint under half a texel: one probe); 0 when both vectors are 0 (a point)
///   lambda = max(log2 q, log2 |r_max| - k 2^G) (unbounded: the second term alone), rounded
///   half up from G to 8 fraction bits and saturated to SQ6.8; a point: the smallest lambda.
/// rho is never negative (area <= |r1||r2| <= smax, and lg is monotonic), so its rounding is
/// an unsigned add and shift. Every log-domain value fits SW = F + 8 bits signed: at most
/// (2D + 34) 2^F and at least -(2D + 17) 2^F, with D <= 24.
///
/// Pipeline (each stage a register with valid; a stage loads when it is empty or passes its
/// fragment on; one fragment per clock):
///   S1 request   the request as it came
///   S2 shift     sh and the shifted magnitudes and signs (|c|, their OR, its leading one)
///   S3 products  the six D x D products: four squares, two cross terms (unsigned, signs apart)
///   S4 squares   s1, s2, area; the longer vector (the direction is chosen here: only its two
///                components travel on), smax and the second operand
///   S5 logs      lg(smax), lg(second) (two tmu_footprint_log2); the cap of k from smax's
///                leading one
///   S6 log sums  log2 |r_max|, log2 q, rho
///   S7 plan      k, lambda: the plan_* outputs
/// A fragment accepted at an edge is on plan_* 7 cycles later when nothing stalls.
/// stat_busy_o: a fragment is in a stage (0 whenever the setup is quiet).
///
/// Configuration (cfg_*): quasi-static. cfg_log2_max_probes_i above 4 acts as 4 (an
/// assertion flags it).
///
/// Example (D 12, T 7, F 8, heights, max 16 probes): r1 = (8, 0), r2 = (0, 1) texels (raw
/// 0x800, 0, 0, 0x100): sh = 0, s1 = 2^22, s2 = 2^16, area = 2^19; lg(s1) = 22 2^8,
/// lg(area) = 19 2^8 (powers of two are exact); log2 |r1| = (5632 - 4096) / 512 = 3.0,
/// rho = 1536 / 512 = 3.0, k = 3 (8 probes along r1), lambda = max(log2 q = 0.0, 3.0 - 3) = 0.0.
module tmu_footprint_setup #(
  /// D: significant bits of the derivative components, 6..24.
  parameter int unsigned DerivBits   = 12,
  /// T: mantissa bits indexing the log2 table, 1..10.
  parameter int unsigned TableBits   = 7,
  /// F: fraction bits of a logarithm, 1..12.
  parameter int unsigned LogFracBits = 8
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,

  /// At most 2^cfg_log2_max_probes_i probes (0..4); the edge length q: 0 heights, 1 sides.
  input  tmu_pkg::probe_log2_t     cfg_log2_max_probes_i,
  input  tmu_pkg::q_rule_t         cfg_q_rule_i,

  /// The fragment: centre (u, v), derivative vectors r1 = (r1u, r1v), r2 = (r2u, r2v), shade.
  input  logic                     req_valid_i,
  output logic                     req_ready_o,
  input  tmu_pkg::tex_coord_t      req_u_i,
  input  tmu_pkg::tex_coord_t      req_v_i,
  input  tmu_pkg::tex_deriv_t      req_r1u_i,
  input  tmu_pkg::tex_deriv_t      req_r1v_i,
  input  tmu_pkg::tex_deriv_t      req_r2u_i,
  input  tmu_pkg::tex_deriv_t      req_r2v_i,
  input  tmu_pkg::rgba8888_t       req_shade_i,

  /// The plan: the centre, the marching direction (r1, or r2 when it is longer; as it came),
  /// the shade, k = log2 N and every probe's lambda.
  output logic                     plan_valid_o,
  input  logic                     plan_ready_i,
  output tmu_pkg::tex_coord_t      plan_u_o,
  output tmu_pkg::tex_coord_t      plan_v_o,
  output tmu_pkg::tex_deriv_t      plan_du_o,
  output tmu_pkg::tex_deriv_t      plan_dv_o,
  output tmu_pkg::rgba8888_t       plan_shade_o,
  output tmu_pkg::probe_log2_t     plan_log2_n_o,
  output tmu_pkg::lod_t            plan_lambda_o,

  /// A fragment is in the setup.
  output logic                     stat_busy_o
);

  localparam int unsigned D   = DerivBits;
  localparam int unsigned F   = LogFracBits;
  localparam int unsigned G   = F + 1;                       // log2 of a length
  localparam int unsigned CW  = tmu_pkg::TexDerivW;          // 24
  localparam int unsigned ShW = $clog2(CW + 1);              // sh: 0 .. CW - D
  localparam int unsigned PW  = 2 * D;                       // a product
  localparam int unsigned SqW = 2 * D + 1;                   // s1, s2, area
  localparam int unsigned EW  = $clog2(SqW);                 // e (tmu_footprint_log2)
  localparam int unsigned VW  = $clog2(SqW + 1) + F;         // lg (tmu_footprint_log2)
  localparam int unsigned SW  = F + 8;                       // log-domain values, signed
  localparam int unsigned KW  = tmu_pkg::ProbeLog2W;         // 3
  localparam int unsigned LW  = SW + 8;                      // lambda before saturation
  localparam int unsigned PortFrac = tmu_pkg::TexCoordFrac;  // 8: squares carry 16
  // Probes at least 2^-SpacingLog2 texels apart (golden footprint::plan's cap on k).
  localparam int unsigned SpacingLog2 = 2;
  localparam int unsigned LodW = tmu_pkg::LodW;              // 14
  localparam logic signed [LW-1:0] LambdaMin = -(LW'(1) << (LodW - 1));
  localparam logic signed [LW-1:0] LambdaMax = (LW'(1) << (LodW - 1)) - LW'(1);

  if (D < 6 || D > CW || TableBits < 1 || TableBits > 10 || F < 1 || F > 12) begin : gen_check
    $error("tmu_footprint_setup: DerivBits 6..24, TableBits 1..10, LogFracBits 1..12");
  end
  if (tmu_pkg::TexDerivFrac != 8 || PortFrac != 8 || tmu_pkg::LodFrac != 8 ||
      tmu_pkg::MaxProbeLog2 != 4) begin : gen_check_formats
    $error("tmu_footprint_setup: built for 8 port fraction bits and at most 16 probes");
  end

  // ---- Pipeline control -----------------------------------------------------------------

  logic s1_valid_q, s2_valid_q, s3_valid_q, s4_valid_q, s5_valid_q, s6_valid_q, s7_valid_q;
  logic s1_ready, s2_ready, s3_ready, s4_ready, s5_ready, s6_ready, s7_ready;
  logic req_fire, s2_load, s3_load, s4_load, s5_load, s6_load, s7_load;

  assign s7_ready = !s7_valid_q || plan_ready_i;
  assign s6_ready = !s6_valid_q || s7_ready;
  assign s5_ready = !s5_valid_q || s6_ready;
  assign s4_ready = !s4_valid_q || s5_ready;
  assign s3_ready = !s3_valid_q || s4_ready;
  assign s2_ready = !s2_valid_q || s3_ready;
  assign s1_ready = !s1_valid_q || s2_ready;

  assign req_ready_o = s1_ready;
  assign req_fire    = req_valid_i && s1_ready;
  assign s2_load     = s1_valid_q && s2_ready;
  assign s3_load     = s2_valid_q && s3_ready;
  assign s4_load     = s3_valid_q && s4_ready;
  assign s5_load     = s4_valid_q && s5_ready;
  assign s6_load     = s5_valid_q && s6_ready;
  assign s7_load     = s6_valid_q && s7_ready;

  assign stat_busy_o = s1_valid_q || s2_valid_q || s3_valid_q || s4_valid_q || s5_valid_q ||
                       s6_valid_q || s7_valid_q;

  // The fragment's data that travels along unchanged: centre and shade; the four derivative
  // components until the direction is chosen (S4), then its two.
  tmu_pkg::tex_coord_t s1_u_q, s1_v_q, s2_u_q, s2_v_q, s3_u_q, s3_v_q;
  tmu_pkg::tex_coord_t s4_u_q, s4_v_q, s5_u_q, s5_v_q, s6_u_q, s6_v_q, s7_u_q, s7_v_q;
  tmu_pkg::rgba8888_t  s1_shade_q, s2_shade_q, s3_shade_q, s4_shade_q, s5_shade_q, s6_shade_q;
  tmu_pkg::rgba8888_t  s7_shade_q;
  // r1u, r1v, r2u, r2v: component c at [c * CW +: CW]
  logic [4*CW-1:0]     s1_r_q, s2_r_q, s3_r_q;
  tmu_pkg::tex_deriv_t s4_du_q, s4_dv_q, s5_du_q, s5_dv_q, s6_du_q, s6_dv_q, s7_du_q, s7_dv_q;
  logic [ShW-1:0]      s2_sh_q, s3_sh_q, s4_sh_q, s5_sh_q;

  // ---- S1 -> S2: block-floating shift ------------------------------------------------------

  logic [4*CW-1:0] mag;      // |component c| at [c * CW +: CW]
  logic [3:0]      neg;
  logic [CW-1:0]   mag_or;
  logic [ShW-1:0]  bitlen, sh;
  logic [4*D-1:0]  shifted;  // |a| at [c * D +: D]

  always_comb begin
    mag_or = '0;
    for (int c = 0; c < 4; c++) begin
      neg[c] = s1_r_q[c*CW + CW-1];
      // |c| of a 24-bit two's complement value fits 24 bits unsigned (|-2^23| = 2^23).
      mag[c*CW +: CW] = neg[c] ? -s1_r_q[c*CW +: CW] : s1_r_q[c*CW +: CW];
      mag_or = mag_or | mag[c*CW +: CW];
    end
    // bitlen(max |c|) = bitlen(OR of the magnitudes)
    bitlen = '0;
    for (int b = 0; b < CW; b++) begin
      if (mag_or[b]) bitlen = ShW'(b + 1);
    end
    sh = bitlen > ShW'(D) ? bitlen - ShW'(D) : '0;
    // |c| >> sh has at most D bits: bitlen(|c|) <= bitlen, and bitlen - sh <= D.
    for (int c = 0; c < 4; c++) shifted[c*D +: D] = D'(mag[c*CW +: CW] >> sh);
  end

  logic [4*D-1:0] s2_m_q;  // shifted magnitudes |a1u|, |a1v|, |a2u|, |a2v| at [c * D +: D]
  logic [3:0]     s2_neg_q;

  // ---- S2 -> S3: products -------------------------------------------------------------------

  // Squares of the four, and the cross terms a1u a2v and a1v a2u with their signs apart.
  logic [PW-1:0] s3_sq1u_q, s3_sq1v_q, s3_sq2u_q, s3_sq2v_q;
  logic [PW-1:0] s3_pa_q, s3_pb_q;
  logic          s3_neg_a_q, s3_neg_b_q;

  // ---- S3 -> S4: squared lengths, area, direction ---------------------------------------------

  logic [SqW-1:0] sum1, sum2, area, smax, second;
  logic           r2_longer;

  assign sum1 = SqW'(s3_sq1u_q) + SqW'(s3_sq1v_q);
  assign sum2 = SqW'(s3_sq2u_q) + SqW'(s3_sq2v_q);
  // cross = (-1)^neg_a pa - (-1)^neg_b pb: |pa - pb| when the signs agree, else pa + pb.
  always_comb begin
    if (s3_neg_a_q != s3_neg_b_q) begin
      area = SqW'(s3_pa_q) + SqW'(s3_pb_q);
    end else if (s3_pa_q >= s3_pb_q) begin
      area = SqW'(s3_pa_q - s3_pb_q);
    end else begin
      area = SqW'(s3_pb_q - s3_pa_q);
    end
  end
  assign r2_longer = sum2 > sum1;
  assign smax      = r2_longer ? sum2 : sum1;
  assign second    = cfg_q_rule_i == 1'b1 ? (r2_longer ? sum1 : sum2) : area;

  logic [SqW-1:0] s4_smax_q, s4_second_q;

  // ---- S4 -> S5: logarithms -----------------------------------------------------------------

  logic          lmax_zero, ls_zero;
  logic [EW-1:0] lmax_exp, unused_ls_exp;  // the second operand's leading one: not needed
  logic [VW-1:0] lmax, ls;

  tmu_footprint_log2 #(.XW(SqW), .TableBits(TableBits), .LogFracBits(F)) u_log2_max (
    .x_i     (s4_smax_q),
    .zero_o  (lmax_zero),
    .exp_o   (lmax_exp),
    .value_o (lmax)
  );
  tmu_footprint_log2 #(.XW(SqW), .TableBits(TableBits), .LogFracBits(F)) u_log2_second (
    .x_i     (s4_second_q),
    .zero_o  (ls_zero),
    .exp_o   (unused_ls_exp),
    .value_o (ls)
  );

  // Probes at least 2^-SpacingLog2 texels apart: k <= max(0, floor(log2 |r_max|) +
  // SpacingLog2) = max(0, (e + 2 sh - 16 + 2 SpacingLog2) >> 1), e = floor(log2 smax) (a
  // square carries 16 fraction bits; floor(log2 sqrt x) = floor(floor(log2 x) / 2)); capped at
  // the largest k there is. e + 2 sh <= 47 (the unshifted square's bits).
  localparam int unsigned CapW = 8;  // signed: -16 + 2 SpacingLog2 .. 31 + 2 SpacingLog2
  logic signed [CapW-1:0] cap_num;
  logic [KW-1:0]          k_cap;
  assign cap_num = CapW'(lmax_exp) + CapW'({s4_sh_q, 1'b0}) - CapW'(2 * PortFrac) +
                   CapW'(2 * SpacingLog2);
  always_comb begin
    if (cap_num < 0) begin
      k_cap = '0;
    end else if ((cap_num >>> 1) > CapW'(tmu_pkg::MaxProbeLog2)) begin
      k_cap = KW'(tmu_pkg::MaxProbeLog2);
    end else begin
      k_cap = KW'(cap_num >>> 1);
    end
  end

  logic          s5_point_q, s5_unbounded_q;
  logic [KW-1:0] s5_k_cap_q;
  logic [VW-1:0] s5_lmax_q, s5_ls_q;

  // ---- S5 -> S6: sums of logarithms (G fraction bits) -----------------------------------------

  logic signed [SW-1:0] offset, lmax_s, ls_s, log2_rmax, log2_q, rho;

  assign lmax_s = SW'(s5_lmax_q);  // zero-extended: VW < SW
  assign ls_s   = SW'(s5_ls_q);
  // (2 sh - 16) 2^F: the shift, and the ports' 16 fraction bits of a square.
  assign offset = (SW'({s5_sh_q, 1'b0}) - SW'(2 * PortFrac)) <<< F;
  assign log2_rmax = lmax_s + offset;
  always_comb begin
    if (cfg_q_rule_i == 1'b1) begin  // sides
      log2_q = ls_s + offset;
      rho    = lmax_s - ls_s;
    end else begin  // heights
      log2_q = (ls_s <<< 1) - lmax_s + offset;
      rho    = (lmax_s - ls_s) <<< 1;
    end
  end

  logic                 s6_point_q, s6_unbounded_q;
  logic [KW-1:0]        s6_k_cap_q;
  logic signed [SW-1:0] s6_log2_rmax_q, s6_log2_q_q, s6_rho_q;

  // ---- S6 -> S7: k and lambda ------------------------------------------------------------------

  logic [KW-1:0]        kmax, k_round, k_ratio, k;
  logic [SW-G-1:0]      rho_rounded;
  logic signed [SW-1:0] spread, lambda_g;
  logic signed [LW-1:0] lambda_wide;
  tmu_pkg::lod_t        lambda;

  assign kmax      = cfg_log2_max_probes_i > KW'(tmu_pkg::MaxProbeLog2) ?
                     KW'(tmu_pkg::MaxProbeLog2) : cfg_log2_max_probes_i;
  // round(rho) half up: rho >= 0, so (rho + 2^(G-1)) >> G; above kmax it is clamped.
  assign rho_rounded = (SW - G)'((SW'(s6_rho_q) + (SW'(1) << (G - 1))) >> G);
  assign k_round     = rho_rounded > (SW - G)'(kmax) ? kmax : KW'(rho_rounded);
  // A line (rho infinite): kmax. Then at most the cap (probes half a texel apart at least);
  // a point: one probe.
  assign k_ratio = s6_unbounded_q ? kmax : k_round;
  assign k       = s6_point_q ? '0 : (k_ratio > s6_k_cap_q ? s6_k_cap_q : k_ratio);
  assign spread   = s6_log2_rmax_q - (SW'(k) <<< G);
  assign lambda_g = (s6_unbounded_q || spread > s6_log2_q_q) ? spread : s6_log2_q_q;

  // G to the port's 8 fraction bits, rounded half up (floor of + half), or widened.
  if (G > 8) begin : gen_round
    logic signed [SW:0] biased, dropped;
    assign biased      = (SW + 1)'(lambda_g) + ((SW + 1)'(1) <<< (G - 9));
    assign dropped     = biased >>> (G - 8);
    assign lambda_wide = LW'(dropped);
  end else if (G == 8) begin : gen_exact
    assign lambda_wide = LW'(lambda_g);
  end else begin : gen_widen
    assign lambda_wide = LW'(lambda_g) <<< (8 - G);
  end
  always_comb begin
    if (s6_point_q || lambda_wide < LambdaMin) begin
      lambda = LodW'(LambdaMin);  // both vectors zero: the finest level
    end else if (lambda_wide > LambdaMax) begin
      lambda = LodW'(LambdaMax);
    end else begin
      lambda = LodW'(lambda_wide);
    end
  end

  tmu_pkg::probe_log2_t s7_k_q;
  tmu_pkg::lod_t        s7_lambda_q;

  assign plan_valid_o  = s7_valid_q;
  assign plan_u_o      = s7_u_q;
  assign plan_v_o      = s7_v_q;
  assign plan_du_o     = s7_du_q;
  assign plan_dv_o     = s7_dv_q;
  assign plan_shade_o  = s7_shade_q;
  assign plan_log2_n_o = s7_k_q;
  assign plan_lambda_o = s7_lambda_q;

  // ---- Flops ------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_valid_q <= 1'b0;
      s2_valid_q <= 1'b0;
      s3_valid_q <= 1'b0;
      s4_valid_q <= 1'b0;
      s5_valid_q <= 1'b0;
      s6_valid_q <= 1'b0;
      s7_valid_q <= 1'b0;
    end else begin
      s1_valid_q <= req_fire || (s1_valid_q && !s2_ready);
      s2_valid_q <= s2_load || (s2_valid_q && !s3_ready);
      s3_valid_q <= s3_load || (s3_valid_q && !s4_ready);
      s4_valid_q <= s4_load || (s4_valid_q && !s5_ready);
      s5_valid_q <= s5_load || (s5_valid_q && !s6_ready);
      s6_valid_q <= s6_load || (s6_valid_q && !s7_ready);
      s7_valid_q <= s7_load || (s7_valid_q && !plan_ready_i);
    end
  end

  // Data registers are read only while their stage is valid: no reset.
  always_ff @(posedge clk_i) begin
    if (req_fire) begin
      s1_u_q     <= req_u_i;
      s1_v_q     <= req_v_i;
      s1_shade_q <= req_shade_i;
      s1_r_q     <= {req_r2v_i, req_r2u_i, req_r1v_i, req_r1u_i};
    end
    if (s2_load) begin
      s2_u_q     <= s1_u_q;
      s2_v_q     <= s1_v_q;
      s2_shade_q <= s1_shade_q;
      s2_r_q     <= s1_r_q;
      s2_m_q     <= shifted;
      s2_neg_q   <= neg;
      s2_sh_q    <= sh;
    end
    if (s3_load) begin
      s3_u_q     <= s2_u_q;
      s3_v_q     <= s2_v_q;
      s3_shade_q <= s2_shade_q;
      s3_r_q     <= s2_r_q;
      s3_sh_q    <= s2_sh_q;
      s3_sq1u_q  <= PW'(s2_m_q[0*D +: D]) * PW'(s2_m_q[0*D +: D]);
      s3_sq1v_q  <= PW'(s2_m_q[1*D +: D]) * PW'(s2_m_q[1*D +: D]);
      s3_sq2u_q  <= PW'(s2_m_q[2*D +: D]) * PW'(s2_m_q[2*D +: D]);
      s3_sq2v_q  <= PW'(s2_m_q[3*D +: D]) * PW'(s2_m_q[3*D +: D]);
      s3_pa_q    <= PW'(s2_m_q[0*D +: D]) * PW'(s2_m_q[3*D +: D]);  // |a1u a2v|
      s3_pb_q    <= PW'(s2_m_q[1*D +: D]) * PW'(s2_m_q[2*D +: D]);  // |a1v a2u|
      s3_neg_a_q <= s2_neg_q[0] ^ s2_neg_q[3];
      s3_neg_b_q <= s2_neg_q[1] ^ s2_neg_q[2];
    end
    if (s4_load) begin
      s4_u_q      <= s3_u_q;
      s4_v_q      <= s3_v_q;
      s4_shade_q  <= s3_shade_q;
      s4_du_q     <= r2_longer ? s3_r_q[2*CW +: CW] : s3_r_q[0*CW +: CW];
      s4_dv_q     <= r2_longer ? s3_r_q[3*CW +: CW] : s3_r_q[1*CW +: CW];
      s4_sh_q     <= s3_sh_q;
      s4_smax_q   <= smax;
      s4_second_q <= second;
    end
    if (s5_load) begin
      s5_u_q         <= s4_u_q;
      s5_v_q         <= s4_v_q;
      s5_shade_q     <= s4_shade_q;
      s5_du_q        <= s4_du_q;
      s5_dv_q        <= s4_dv_q;
      s5_sh_q        <= s4_sh_q;
      s5_point_q     <= lmax_zero;
      s5_unbounded_q <= ls_zero;
      s5_k_cap_q     <= k_cap;
      s5_lmax_q      <= lmax;
      s5_ls_q        <= ls;
    end
    if (s6_load) begin
      s6_u_q         <= s5_u_q;
      s6_v_q         <= s5_v_q;
      s6_shade_q     <= s5_shade_q;
      s6_du_q        <= s5_du_q;
      s6_dv_q        <= s5_dv_q;
      s6_point_q     <= s5_point_q;
      s6_unbounded_q <= s5_unbounded_q;
      s6_k_cap_q     <= s5_k_cap_q;
      s6_log2_rmax_q <= log2_rmax;
      s6_log2_q_q    <= log2_q;
      s6_rho_q       <= rho;
    end
    if (s7_load) begin
      s7_u_q      <= s6_u_q;
      s7_v_q      <= s6_v_q;
      s7_shade_q  <= s6_shade_q;
      s7_du_q     <= s6_du_q;
      s7_dv_q     <= s6_dv_q;
      s7_k_q      <= k;
      s7_lambda_q <= lambda;
    end
  end

  // ---- Assertions ---------------------------------------------------------------------------
`ifndef SYNTHESIS
  // rho is never negative (area <= smax, sides: smin <= smax; lg is monotonic).
  property p_rho_not_negative;
    @(posedge clk_i) disable iff (!rst_ni) s6_valid_q |-> !s6_rho_q[SW-1];
  endproperty
  a_rho_not_negative: assert property (p_rho_not_negative);

  // The configuration is within its range (0..4 probes' log2).
  property p_max_probes_in_range;
    @(posedge clk_i) disable iff (!rst_ni)
      stat_busy_o |-> cfg_log2_max_probes_i <= KW'(tmu_pkg::MaxProbeLog2);
  endproperty
  a_max_probes_in_range: assert property (p_max_probes_in_range);
`endif

endmodule
