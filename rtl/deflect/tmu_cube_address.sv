/// The cube environment map's addressing unit (000 §7, §5 "fourth": "dividing by the largest
/// component of the vector"; golden deflect::cube_address in golden/deflect/cube_map.hpp, the
/// specification): a reflection vector R = (x, y, z), the coordinate generator's (uR, vR, wR),
/// to one of six faces and a texel coordinate on a face of 2^L texels. One vector per clock.
///
///   major axis  the largest |component|, ties to the earlier of x, y, z (an edge or a corner
///               of the cube belongs to one face); face = 2 axis + (major < 0), OpenGL's order
///               +X, -X, +Y, -Y, +Z, -Z; the zero vector is +X
///   (sc, tc)    OpenGL's face coordinates, ma = |major|:
///                 +X: -z, -y   -X: +z, -y   +Y: +x, +z   -Y: +x, -z   +Z: +x, -y   -Z: -x, -y
///   divide      r = |sc| / ma (the normal encoder's divider, tmu_normal_divider, UQ1.16)
///   s           2^15 +- (r >> 1) by sc's sign (UQ0.16, 0 .. 2^16); likewise t from tc
///   u           ((s << L) + 2^7) >> 8: TexCoord SQ16.8, texel centres at i + 0.5; likewise v
/// A zero |sc| divides to r = 0 whatever its sign, so the sign of a zero component (-0 is +0
/// here) never matters; ma = 0 (the zero vector) gives r = 0 too: the face's centre.
///
/// L is any value of the 4-bit port: the unit computes golden's formula for all of them
/// (2^23 at most, L = 15), though faces are 2^0 .. 2^10 texels (MaxMipLog2).
///
/// Pipeline. Each stage is a register with a valid bit; the whole pipeline advances when the
/// output register is empty or being taken, and stalls otherwise (one vector per clock while
/// the output is taken):
///   S1 input     signs and magnitudes, L
///   S2 major     the three compares, the face, ma, |sc|, |tc| and their signs
///   S3-S6        two dividers side by side (u and v, both over ma), stages A-D: normalise and
///                seed, 2 - d r0, the Newton-Raphson step, the quotient
///   S7 output    s, t and the shift to the face's size: out_face_o, out_u_o, out_v_o
/// A vector accepted at an edge is on the output 6 edges later when nothing stalls (latency
/// 7 cycles).
///
/// Example (L = 8): R = (16384, 8192, 0) (+X, 1.0 by 0.5): ma = 16384, sc = -z = 0 (r = 0,
/// s = 2^15), tc = -y = -8192 (r = 32767: 0.5 one LSB low, s = 2^15 - 16383 = 16385): u =
/// (2^15 2^8 + 128) >> 8 = 32768 (128.0 texels), v = (16385 2^8 + 128) >> 8 = 16385 (64.004).
module tmu_cube_address #(
  /// S: index bits of the dividers' reciprocal seed table, 2..12.
  parameter int unsigned SeedBits = 7
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  /// R, SQ2.14 components of any length (zero included), and the face's log2 size L (a
  /// per-request configuration, 0..10 in use).
  input  logic                 in_valid_i,
  output logic                 in_ready_o,
  input  tmu_pkg::unit_comp_t  in_x_i,
  input  tmu_pkg::unit_comp_t  in_y_i,
  input  tmu_pkg::unit_comp_t  in_z_i,
  input  tmu_pkg::mip_log2_t   in_face_log2_i,

  /// The face (0 .. 5: +X, -X, +Y, -Y, +Z, -Z) and the texel coordinate on it.
  output logic                 out_valid_o,
  input  logic                 out_ready_i,
  output tmu_pkg::cube_face_t  out_face_o,
  output tmu_pkg::tex_coord_t  out_u_o,
  output tmu_pkg::tex_coord_t  out_v_o
);

  localparam int unsigned NumStages = 7;
  localparam int unsigned LW        = tmu_pkg::MipLog2W;
  localparam int unsigned CoordW    = tmu_pkg::TexCoordW;

  if (tmu_pkg::UnitCompW != 16 || LW != 4 || CoordW != 24 || tmu_pkg::CubeFaceW != 3)
  begin : gen_check_formats
    $error("tmu_cube_address: built for 16-bit components, 4-bit L, 24-bit coordinates");
  end

  // ---- Pipeline control: tmu_pipe_ctrl ------------------------------------------------------

  // valid[j]: stage j holds a vector; load[j]: stage j takes stage j - 1's at this edge.
  // The stages load on load[j]; nothing here reads their valids.
  // verilator lint_off UNUSEDSIGNAL
  logic [NumStages:1] valid, load;
  // verilator lint_on UNUSEDSIGNAL

  tmu_pipe_ctrl #(.NumStages(NumStages)) u_pipe_ctrl (.clk_i, .rst_ni, .in_valid_i, .in_ready_o,
    .out_valid_o, .out_ready_i, .valid_o(valid), .load_o(load));

  // ---- -> S1: signs and magnitudes ------------------------------------------------------------

  // |-32768| = 32768 fits 16 bits unsigned.
  function automatic logic [15:0] magnitude(input tmu_pkg::unit_comp_t v);
    magnitude = v[15] ? 16'(-v) : 16'(v);
  endfunction

  logic            s1_sx_q, s1_sy_q, s1_sz_q;
  logic [15:0]     s1_a_q, s1_b_q, s1_c_q;
  logic [LW-1:0]   s1_log2_q;

  // ---- S1 -> S2: the major axis and the face coordinates ----------------------------------------

  logic        x_major, y_major;
  logic [2:0]  face;
  logic [15:0] major, sc_mag, tc_mag;
  logic        sc_neg, tc_neg;

  // Ties to the earlier axis: x before y before z.
  assign x_major = s1_a_q >= s1_b_q && s1_a_q >= s1_c_q;
  assign y_major = !x_major && s1_b_q >= s1_c_q;

  always_comb begin
    if (x_major) begin
      face  = {2'd0, s1_sx_q};
      major = s1_a_q;
    end else if (y_major) begin
      face  = {2'd1, s1_sy_q};
      major = s1_b_q;
    end else begin
      face  = {2'd2, s1_sz_q};
      major = s1_c_q;
    end
    // (sc, tc) as sign and magnitude: a negated component is negative when it is positive;
    // a zero one divides to 0 whatever its sign.
    unique case (face)
      3'd0:    {sc_neg, sc_mag, tc_neg, tc_mag} = {!s1_sz_q, s1_c_q, !s1_sy_q, s1_b_q};  // +X
      3'd1:    {sc_neg, sc_mag, tc_neg, tc_mag} = {s1_sz_q, s1_c_q, !s1_sy_q, s1_b_q};   // -X
      3'd2:    {sc_neg, sc_mag, tc_neg, tc_mag} = {s1_sx_q, s1_a_q, s1_sz_q, s1_c_q};    // +Y
      3'd3:    {sc_neg, sc_mag, tc_neg, tc_mag} = {s1_sx_q, s1_a_q, !s1_sz_q, s1_c_q};   // -Y
      3'd4:    {sc_neg, sc_mag, tc_neg, tc_mag} = {s1_sx_q, s1_a_q, !s1_sy_q, s1_b_q};   // +Z
      default: {sc_neg, sc_mag, tc_neg, tc_mag} = {!s1_sx_q, s1_a_q, !s1_sy_q, s1_b_q};  // -Z
    endcase
  end

  logic [15:0] s2_ma_q, s2_sc_q, s2_tc_q;

  // {face, sc's sign, tc's sign, L} travel from S2 to S7.
  typedef logic [LW+4:0] flags_t;
  flags_t s2_flags_q, s3_flags_q, s4_flags_q, s5_flags_q, s6_flags_q;

  // ---- S2 -> S6: the dividers -----------------------------------------------------------------

  logic [16:0] r_u, r_v;  // UQ1.16, S6

  tmu_normal_divider #(.SeedBits(SeedBits)) u_divider_u (
    .clk_i  (clk_i),
    .load_i (load[6:3]),
    .num_i  (32'(s2_sc_q)),
    .den_i  (32'(s2_ma_q)),
    .t_o    (r_u)
  );
  tmu_normal_divider #(.SeedBits(SeedBits)) u_divider_v (
    .clk_i  (clk_i),
    .load_i (load[6:3]),
    .num_i  (32'(s2_tc_q)),
    .den_i  (32'(s2_ma_q)),
    .t_o    (r_v)
  );

  // ---- S6 -> S7: the texel coordinates --------------------------------------------------------

  // s = 2^15 +- (r >> 1), 0 .. 2^16 (r <= 2^16); then ((s << L) + 2^7) >> 8, < 2^24 for every
  // 4-bit L (2^31 + 2^7 at most before the shift).
  function automatic logic [CoordW-1:0] texel_coord(input logic [16:0] r, input logic neg,
                                                    input logic [LW-1:0] log2);
    logic [16:0] half, s;
    logic [31:0] scaled;
    half   = r >> 1;
    s      = neg ? 17'h0_8000 - half : 17'h0_8000 + half;
    scaled = (32'(s) << log2) + 32'd128;
    texel_coord = CoordW'(scaled >> 8);
  endfunction

  logic [2:0]    face_s6;
  logic          sc_neg_s6, tc_neg_s6;
  logic [LW-1:0] log2_s6;
  assign {face_s6, sc_neg_s6, tc_neg_s6, log2_s6} = s6_flags_q;

  tmu_pkg::cube_face_t s7_face_q;
  tmu_pkg::tex_coord_t s7_u_q, s7_v_q;

  assign out_face_o = s7_face_q;
  assign out_u_o    = s7_u_q;
  assign out_v_o    = s7_v_q;

  // ---- Data registers: only read while their stage is valid, no reset --------------------------

  always_ff @(posedge clk_i) begin
    if (load[1]) begin
      {s1_sz_q, s1_sy_q, s1_sx_q} <= {in_z_i[15], in_y_i[15], in_x_i[15]};
      s1_a_q    <= magnitude(in_x_i);
      s1_b_q    <= magnitude(in_y_i);
      s1_c_q    <= magnitude(in_z_i);
      s1_log2_q <= in_face_log2_i;
    end
    if (load[2]) begin
      s2_flags_q <= {face, sc_neg, tc_neg, s1_log2_q};
      s2_ma_q    <= major;
      s2_sc_q    <= sc_mag;
      s2_tc_q    <= tc_mag;
    end
    if (load[3]) s3_flags_q <= s2_flags_q;
    if (load[4]) s4_flags_q <= s3_flags_q;
    if (load[5]) s5_flags_q <= s4_flags_q;
    if (load[6]) s6_flags_q <= s5_flags_q;
    if (load[7]) begin
      s7_face_q <= face_s6;
      s7_u_q    <= texel_coord(r_u, sc_neg_s6, log2_s6);
      s7_v_q    <= texel_coord(r_v, tc_neg_s6, log2_s6);
    end
  end

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // The dividers see a face coordinate no larger than the major component.
  a_ratio_at_most_one: assert property (@(posedge clk_i) disable iff (!rst_ni)
      load[3] |-> (s2_sc_q <= s2_ma_q && s2_tc_q <= s2_ma_q));
  // Six faces.
  a_face_in_range: assert property (@(posedge clk_i) disable iff (!rst_ni)
      out_valid_o |-> out_face_o <= 3'd5);
`endif

endmodule
