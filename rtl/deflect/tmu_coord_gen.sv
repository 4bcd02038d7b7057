/// The shading- and environment-map coordinate generator (001 §5, eq. 17-22; golden
/// CoordTables in golden/deflect/coord_tables.hpp, evaluated as eval_coords in
/// golden/deflect/coord_eval.hpp): seven tables indexed by a normal's angles give
///   uN = F1 F2 + F3,  vN = F1 G2 + G3,  hN = F1 H2 + H3     (rounded half up to SQ2.14)
///   uR = 2 hN uN,  vR = 2 hN vN,  wR = 2 hN^2 - 1          (rounded half up, saturated)
/// with A = PhiBits, Q = 2^(A-2), W = ValueBits:
///   theta tables F1, F3, G3, H3: Q entries read at |theta| (theta's low A - 2 bits); F3, G3,
///     H3 negated when theta's sign bit (bit A - 2) is set (also for a -0 input, as the
///     golden model does: a view frame's F3(0), G3(0), H3(0) are 0);
///   phi tables F2, G2, H2: 2Q entries read at phi mod 2Q (phi's low A - 1 bits), negated
///     when phi >= 2Q (bit A - 1): F2(phi + pi) = -F2(phi).
///
/// Table write port (always ready, one write per clock): tw_table_i 0 F1, 1 F2, 2 F3, 3 G2,
/// 4 G3, 5 H2, 6 H3. A write to table 7 or beyond its table's entries (tw_addr_i >= Q for a
/// theta table, >= 2Q for a phi table) changes nothing. The entry is tw_value_i's low W bits, the most negative
/// value -2^(W-1) raised to -(2^(W-1) - 1): every entry is within +-(2^(W-1) - 1), so
/// negating it never overflows and uN, vN, hN fit SQ2.14 (tmu_coord_dot). The tables have no
/// reset: load every entry a request will read.
///
/// Ordering of writes and requests: a request reads all seven tables in the cycle it is
/// accepted (asynchronous reads, registered in S1), and a write changes its entry at the edge
/// it is accepted. So a request sees exactly the writes accepted at earlier edges, whatever
/// the pipeline and the output are doing: in the order the items are sent, when they are sent
/// one per clock, as the golden model applies them. A write and a request accepted at the
/// same edge: the request reads the table before the write.
///
/// Pipeline (each stage a register with valid; a stage loads when it is empty or passes its
/// normal on, so bubbles close up and one normal per clock passes without stalls):
///   S1 entries    the seven entries and the two signs
///   S2 dots       uN, vN, hN (tmu_coord_dot: products, sums, rounding)
///   S3 output     uN, vN and uR, vR, wR (tmu_coord_reflect: products, rounding, saturation)
/// A request accepted at an edge is on out_* after the second edge that follows (latency
/// 3 registers); in_ready_o follows out_ready_i combinationally through the stages.
///
/// Ports carry the package formats; other parameters use the ports' low bits: phi's low A
/// bits, theta's low A - 1 (sign at bit A - 2), the value's low W bits, the golden model's
/// raw values for that grid and width.
///
/// Example (identity view, W = 10): phi = 0, theta = +0: F1 = 511, F2 = sin 0 = 0,
/// F3 = 0, G2 = 0, G3 = 0, H2 = cos 0 = 511 (1.0 saturated), H3 = 0: uN = vN = 0,
/// hN = (511 * 511 + 8) >> 4 = 16320 (0.9961), uR = vR = 0, wR = 2 hN^2 - 1 =
/// ((16320^2 + 2^12) >> 13) - 16384 = 16129 (0.9844).
module tmu_coord_gen #(
  /// A: phi bits of the sphere grid, 6 .. tmu_pkg::SpherePhiW (the golden TableConfig's 9).
  parameter int unsigned PhiBits   = tmu_pkg::SpherePhiW,
  /// W: bits of a table entry, 8 .. tmu_pkg::CoordValueW (the golden TableConfig's 10).
  parameter int unsigned ValueBits = tmu_pkg::CoordValueW
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,

  /// Table write: entry tw_addr_i of table tw_table_i <= tw_value_i.
  input  logic                       tw_valid_i,
  output logic                       tw_ready_o,
  input  tmu_pkg::coord_table_id_t   tw_table_i,
  input  tmu_pkg::coord_table_addr_t tw_addr_i,
  input  tmu_pkg::coord_value_t      tw_value_i,

  /// A normal's angles on the sphere grid.
  input  logic                       in_valid_i,
  output logic                       in_ready_o,
  input  tmu_pkg::sphere_phi_t       in_phi_i,
  input  tmu_pkg::sphere_theta_t     in_theta_i,

  /// Shading-map coordinates and the reflection vector in the view frame, SQ2.14.
  output logic                       out_valid_o,
  input  logic                       out_ready_i,
  output tmu_pkg::unit_comp_t        out_un_o,
  output tmu_pkg::unit_comp_t        out_vn_o,
  output tmu_pkg::unit_comp_t        out_ur_o,
  output tmu_pkg::unit_comp_t        out_vr_o,
  output tmu_pkg::unit_comp_t        out_wr_o
);

  localparam int unsigned W        = ValueBits;
  localparam int unsigned MagBits  = PhiBits - 2;  // theta table address: |theta|
  localparam int unsigned HalfBits = PhiBits - 1;  // phi table address: phi mod 2Q
  localparam int unsigned Tables   = 7;
  localparam int unsigned AW       = tmu_pkg::CoordTableAddrW;

  if (PhiBits < 6 || PhiBits > tmu_pkg::SpherePhiW || W < 8 || W > tmu_pkg::CoordValueW ||
      tmu_pkg::SphereThetaW != tmu_pkg::SpherePhiW - 1 || AW != tmu_pkg::SpherePhiW - 1)
  begin : gen_check
    $error("tmu_coord_gen: PhiBits must be 6..SpherePhiW, ValueBits 8..CoordValueW");
  end

  // Table ids (coord_table_id_t), and the ones indexed by phi: F2, G2, H2.
  localparam int unsigned F1 = 0, F2 = 1, F3 = 2, G2 = 3, G3 = 4, H2 = 5, H3 = 6;
  localparam logic [Tables-1:0] PhiTables = Tables'((1 << F2) | (1 << G2) | (1 << H2));

  // ---- Write port ---------------------------------------------------------------------------

  logic                theta_addr_ok, phi_addr_ok;
  logic signed [W-1:0] tw_entry;

  // An address must lie inside its table: below Q (theta) or 2Q (phi).
  assign theta_addr_ok = (tw_addr_i >> MagBits) == '0;
  assign phi_addr_ok   = (tw_addr_i >> HalfBits) == '0;
  // -2^(W-1) (only the sign bit set) becomes -(2^(W-1) - 1) by setting the lowest bit.
  assign tw_entry = {tw_value_i[W-1:1],
                     tw_value_i[0] | (tw_value_i[W-1:0] == {1'b1, (W-1)'(0)})};
  assign tw_ready_o = 1'b1;

  // A smaller grid or width ignores the ports' bits above its own.
  logic unused_high_bits;
  assign unused_high_bits = ^{tw_value_i, in_phi_i, in_theta_i};

  // ---- Handshake ----------------------------------------------------------------------------

  logic s1_valid_q, s2_valid_q, out_valid_q;
  logic s1_load, s2_load, out_load, in_fire;

  assign out_load   = !out_valid_q || out_ready_i;
  assign s2_load    = !s2_valid_q || out_load;
  assign s1_load    = !s1_valid_q || s2_load;
  assign in_ready_o = s1_load;
  assign in_fire    = in_valid_i && s1_load;

  // ---- Tables, read at acceptance -----------------------------------------------------------

  // Table t's entry at [t * W +: W] (flat: Yosys 0.23 has no packed arrays of vectors).
  logic [Tables*W-1:0] entry;

  for (genvar t = 0; t < Tables; t++) begin : gen_table
    logic we;
    if (PhiTables[t]) begin : gen_phi
      assign we = tw_valid_i && tw_table_i == tmu_pkg::CoordTableIdW'(t) && phi_addr_ok;
      tmu_coord_table #(.AddrBits(HalfBits), .ValueBits(W)) u_table (
        .clk_i,
        .we_i    (we),
        .waddr_i (tw_addr_i[HalfBits-1:0]),
        .wdata_i (tw_entry),
        .raddr_i (in_phi_i[HalfBits-1:0]),
        .rdata_o (entry[t*W +: W])
      );
    end else begin : gen_theta
      assign we = tw_valid_i && tw_table_i == tmu_pkg::CoordTableIdW'(t) && theta_addr_ok;
      tmu_coord_table #(.AddrBits(MagBits), .ValueBits(W)) u_table (
        .clk_i,
        .we_i    (we),
        .waddr_i (tw_addr_i[MagBits-1:0]),
        .wdata_i (tw_entry),
        .raddr_i (in_theta_i[MagBits-1:0]),
        .rdata_o (entry[t*W +: W])
      );
    end
  end

  // ---- S1: entries --------------------------------------------------------------------------

  logic [Tables*W-1:0] entry_q;
  logic                phi_neg_q, theta_neg_q;

  // ---- S2: uN, vN, hN -----------------------------------------------------------------------

  tmu_pkg::unit_comp_t un, vn, hn, un_q, vn_q, hn_q;

  tmu_coord_dot #(.ValueBits(W)) u_dot_u (
    .cos_i(entry_q[F1*W +: W]), .phi_entry_i(entry_q[F2*W +: W]), .phi_neg_i(phi_neg_q),
    .theta_entry_i(entry_q[F3*W +: W]), .theta_neg_i(theta_neg_q), .dot_o(un));
  tmu_coord_dot #(.ValueBits(W)) u_dot_v (
    .cos_i(entry_q[F1*W +: W]), .phi_entry_i(entry_q[G2*W +: W]), .phi_neg_i(phi_neg_q),
    .theta_entry_i(entry_q[G3*W +: W]), .theta_neg_i(theta_neg_q), .dot_o(vn));
  tmu_coord_dot #(.ValueBits(W)) u_dot_h (
    .cos_i(entry_q[F1*W +: W]), .phi_entry_i(entry_q[H2*W +: W]), .phi_neg_i(phi_neg_q),
    .theta_entry_i(entry_q[H3*W +: W]), .theta_neg_i(theta_neg_q), .dot_o(hn));

  // ---- S3: the output -----------------------------------------------------------------------

  tmu_pkg::unit_comp_t ur, vr, wr;
  tmu_pkg::unit_comp_t out_un_q, out_vn_q, out_ur_q, out_vr_q, out_wr_q;

  tmu_coord_reflect #(.MinusOne(1'b0)) u_reflect_u (.a_i(hn_q), .b_i(un_q), .r_o(ur));
  tmu_coord_reflect #(.MinusOne(1'b0)) u_reflect_v (.a_i(hn_q), .b_i(vn_q), .r_o(vr));
  tmu_coord_reflect #(.MinusOne(1'b1)) u_reflect_w (.a_i(hn_q), .b_i(hn_q), .r_o(wr));

  assign out_valid_o = out_valid_q;
  assign out_un_o    = out_un_q;
  assign out_vn_o    = out_vn_q;
  assign out_ur_o    = out_ur_q;
  assign out_vr_o    = out_vr_q;
  assign out_wr_o    = out_wr_q;

  // ---- Flops --------------------------------------------------------------------------------

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_valid_q  <= 1'b0;
      s2_valid_q  <= 1'b0;
      out_valid_q <= 1'b0;
    end else begin
      if (s1_load) s1_valid_q <= in_valid_i;
      if (s2_load) s2_valid_q <= s1_valid_q;
      if (out_load) out_valid_q <= s2_valid_q;
    end
  end

  // Data is only observed while its stage is valid: no reset.
  always_ff @(posedge clk_i) begin
    if (in_fire) begin
      entry_q     <= entry;
      phi_neg_q   <= in_phi_i[PhiBits-1];
      theta_neg_q <= in_theta_i[MagBits];
    end
    if (s1_valid_q && s2_load) begin
      un_q <= un;
      vn_q <= vn;
      hn_q <= hn;
    end
    if (s2_valid_q && out_load) begin
      out_un_q <= un_q;
      out_vn_q <= vn_q;
      out_ur_q <= ur;
      out_vr_q <= vr;
      out_wr_q <= wr;
    end
  end

`ifndef SYNTHESIS
  // Every stored entry is within +-(2^(W-1) - 1): the negations in tmu_coord_dot are exact.
  property p_entry_in_range;
    @(posedge clk_i) disable iff (!rst_ni) tw_valid_i |-> tw_entry != {1'b1, (W-1)'(0)};
  endproperty
  a_entry_in_range: assert property (p_entry_in_range);
`endif

endmodule
