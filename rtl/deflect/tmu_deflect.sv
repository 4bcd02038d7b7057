/// The bump deflection unit with its cache (001 §4.4, Fig. 5; §6.2, Fig. 7; golden
/// deflect::DeflectionUnit in golden/deflect/s2s_map.hpp, the specification): a bump texel D
/// = (phi_D, theta_D) rotated onto the surface of normal N = (phi_N, theta_N) by the roll
/// phi' = phi_D - theta_N, one look-up of the first-octant spherical-to-spherical map and the
/// yaw + phi_N. Each result carries its access: hit, miss or bypass.
///
/// Pipeline (one request per clock while it hits or bypasses):
///   in    tmu_bump_unpack: the texel's angles D; tmu_deflect_address: phi', the octant
///         reduction, the block and the entry in it
///   S1    the look-up: the block's tag against the MBR (memory buffer register: one block
///         of 4 x 4 entries and its tag, empty after reset). A hit reads the entry from the
///         MBR. k = Q (the z = 0 column) needs no entry: (l_phi, l_theta) = (Q, min(Q -
///         k_theta, Q - 1)), and the MBR is left as it is. A miss requests the block from
///         the map memory (map_req_valid_o for one cycle, one outstanding) and S1 waits;
///         the cycle the block arrives it is written to the MBR and, forwarded from the
///         response, gives the entry. tmu_deflect_expand moves the entry back to the
///         octant and adds phi_N.
///   out   the output register.
/// S1 is the only place the MBR is read or written, in request order, so every request sees
/// the MBR its predecessors left: the golden model's sequential semantics, access codes
/// included. A request accepted at an edge is on the outputs after the next edge (latency 2
/// when nothing stalls). A miss holds S1 for the memory's latency L (request to response,
/// L >= 1): each miss costs L cycles of throughput.
///
/// The map memory answers each request with the whole block on map_resp_data_i: entry o =
/// (k_theta & 3) 4 + (k & 3) at bits EntryW o +: EntryW, an entry being l_phi << (A-2) |
/// l_theta. The response comes one or more cycles after the request; the unit takes it the
/// cycle map_resp_valid_i is high (no ready: the unit always waits for it).
///
/// Ports use A-derived widths; at the default A = 9 they are tmu_pkg::sphere_phi_t (phi),
/// sphere_theta_t (theta: sign bit A-2, magnitude below), s2s_block_addr_t and 16 x
/// s2s_entry_t.
///
/// Example (A = 9, empty MBR, L = 4): N = (5, +30), the texel 0x0A_05_80, D = (10, -5):
/// phi' = 492 (quadrant 3), k = 20, k_theta = 5, sx = 1, sy = sz = 0, block 37 (a miss): the
/// request leaves the cycle after the input is accepted, the block arrives 4 cycles later and
/// ENTRY[5][20] = (l_phi 5, l_theta 20) gives phi = 4Q - 5 + 5 = 0 (modulo 4Q), theta = +20:
/// the output (0, +20, miss) is valid the cycle after. The same texel again is a hit and
/// follows back to back.
module tmu_deflect #(
  /// A: bits of phi (the grid has 2^A x 2^(A-1) patches), 6..12.
  parameter int unsigned PhiBits = 9
) (
  input  logic                         clk_i,
  input  logic                         rst_ni,

  /// Request: the surface normal N (angles on the grid) and the bump map's texel, which
  /// holds D (tmu_bump_unpack).
  input  logic                         in_valid_i,
  output logic                         in_ready_o,
  input  logic [PhiBits-1:0]           in_normal_phi_i,
  input  logic [PhiBits-2:0]           in_normal_theta_i,
  input  tmu_pkg::rgb888_t             in_bump_texel_i,

  /// Result: the deflected normal and how the map was read (0 hit, 1 miss, 2 bypass).
  output logic                         out_valid_o,
  input  logic                         out_ready_i,
  output logic [PhiBits-1:0]           out_phi_o,
  output logic [PhiBits-2:0]           out_theta_o,
  output tmu_pkg::map_access_t         out_access_o,

  /// Map memory: a block request (one outstanding) and its response, 16 entries.
  output logic                         map_req_valid_o,
  output logic [2*(PhiBits-4)-1:0]     map_req_block_o,
  input  logic                         map_resp_valid_i,
  input  logic [16*(2*PhiBits-3)-1:0]  map_resp_data_i
);

  localparam int unsigned A       = PhiBits;
  localparam int unsigned MagBits = A - 2;
  localparam int unsigned EntryW  = 2 * A - 3;
  localparam int unsigned BlockW  = 2 * (A - 4);
  localparam int unsigned Entries = 16;
  localparam logic [MagBits-1:0] QMinus1 = '1;

  localparam tmu_pkg::map_access_t AccessHit    = 2'd0;
  localparam tmu_pkg::map_access_t AccessMiss   = 2'd1;
  localparam tmu_pkg::map_access_t AccessBypass = 2'd2;

  if (A < 6 || A > 12) begin : gen_check
    $error("tmu_deflect: PhiBits 6..12");
  end
  if (tmu_pkg::S2sBlockEntries != Entries) begin : gen_check_block
    $error("tmu_deflect: built for blocks of 4 x 4 entries");
  end

  // ---- Address (combinational, in front of S1) ---------------------------------------------

  logic [A-1:0]       in_bump_phi;
  logic [A-2:0]       in_bump_theta;

  tmu_bump_unpack #(.PhiBits(A)) u_unpack (
    .texel_i(in_bump_texel_i),
    .phi_o  (in_bump_phi),
    .theta_o(in_bump_theta)
  );

  logic               in_sx, in_sy, in_sz, in_bypass;
  logic [MagBits-1:0] in_k_theta;
  logic [BlockW-1:0]  in_block;
  logic [3:0]         in_offset;

  tmu_deflect_address #(.PhiBits(A)) u_address (
    .bump_phi_i    (in_bump_phi),
    .bump_theta_i  (in_bump_theta),
    .normal_theta_i(in_normal_theta_i),
    .sx_o          (in_sx),
    .sy_o          (in_sy),
    .sz_o          (in_sz),
    .bypass_o      (in_bypass),
    .k_theta_o     (in_k_theta),
    .block_o       (in_block),
    .offset_o      (in_offset)
  );

  // ---- Control ---------------------------------------------------------------------------

  logic               s1_valid_q, s1_missed_q, out_valid_q;
  logic               fetching_q;   // a block request is outstanding
  logic               mbr_valid_q;
  logic [BlockW-1:0]  mbr_tag_q;
  logic [Entries*EntryW-1:0] mbr_data_q;

  // S1's request (data: no reset, observed only while s1_valid_q).
  logic               s1_sx_q, s1_sy_q, s1_sz_q, s1_bypass_q;
  logic [MagBits-1:0] s1_k_theta_q;
  logic [BlockW-1:0]  s1_block_q;
  logic [3:0]         s1_offset_q;
  logic [A-1:0]       s1_normal_phi_q;

  logic tag_hit, resp_fill, entry_ready, out_free, s1_advance, in_fire;

  assign tag_hit     = mbr_valid_q && mbr_tag_q == s1_block_q;
  assign resp_fill   = fetching_q && map_resp_valid_i;
  // S1 can leave once its entry is known: bypassed, in the MBR, or arriving now.
  assign entry_ready = s1_bypass_q || tag_hit || resp_fill;
  assign out_free    = !out_valid_q || out_ready_i;
  assign s1_advance  = s1_valid_q && entry_ready && out_free;
  assign in_ready_o  = !s1_valid_q || s1_advance;
  assign in_fire     = in_valid_i && in_ready_o;

  // A miss asks once: while the request is outstanding fetching_q is set, and after the
  // fill the tag matches.
  assign map_req_valid_o = s1_valid_q && !s1_bypass_q && !tag_hit && !fetching_q;
  assign map_req_block_o = s1_block_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_valid_q  <= 1'b0;
      s1_missed_q <= 1'b0;
      fetching_q  <= 1'b0;
      mbr_valid_q <= 1'b0;
      out_valid_q <= 1'b0;
    end else begin
      if (in_ready_o) s1_valid_q <= in_valid_i;
      // The request in S1 missed: it reports a miss whenever it leaves.
      if (in_fire) s1_missed_q <= 1'b0;
      else if (map_req_valid_o) s1_missed_q <= 1'b1;
      if (map_req_valid_o) fetching_q <= 1'b1;
      else if (map_resp_valid_i) fetching_q <= 1'b0;
      if (resp_fill) mbr_valid_q <= 1'b1;
      if (out_free) out_valid_q <= s1_advance;
    end
  end

  always_ff @(posedge clk_i) begin
    if (in_fire) begin
      s1_sx_q         <= in_sx;
      s1_sy_q         <= in_sy;
      s1_sz_q         <= in_sz;
      s1_bypass_q     <= in_bypass;
      s1_k_theta_q    <= in_k_theta;
      s1_block_q      <= in_block;
      s1_offset_q     <= in_offset;
      s1_normal_phi_q <= in_normal_phi_i;
    end
  end

  // The MBR: the block of S1's request, written the cycle it arrives (S1 waits meanwhile,
  // so s1_block_q is the block that was asked for).
  always_ff @(posedge clk_i) begin
    if (resp_fill) begin
      mbr_tag_q  <= s1_block_q;
      mbr_data_q <= map_resp_data_i;
    end
  end

  // ---- S1: the entry, the bypass column, the expansion ---------------------------------------

  logic [EntryW-1:0]  mbr_entry, resp_entry, entry;
  logic [MagBits:0]   l_phi;
  logic [MagBits-1:0] l_theta, bypass_theta;
  logic [A-1:0]       phi;
  logic [A-2:0]       theta;

  // The entry from the MBR, or forwarded from the response that fills it.
  assign mbr_entry  = mbr_data_q[s1_offset_q * EntryW +: EntryW];
  assign resp_entry = map_resp_data_i[s1_offset_q * EntryW +: EntryW];
  assign entry      = resp_fill ? resp_entry : mbr_entry;
  // z = 0: l_phi = Q, l_theta = min(Q - k_theta, Q - 1); Q - k_theta is -k_theta in MagBits
  // bits for k_theta > 0, and k_theta = 0 (the pole) saturates to Q - 1.
  assign bypass_theta = s1_k_theta_q == '0 ? QMinus1 : -s1_k_theta_q;
  assign l_phi   = s1_bypass_q ? {1'b1, MagBits'(0)} : entry[EntryW-1:MagBits];
  assign l_theta = s1_bypass_q ? bypass_theta : entry[MagBits-1:0];

  tmu_deflect_expand #(.PhiBits(A)) u_expand (
    .sx_i        (s1_sx_q),
    .sy_i        (s1_sy_q),
    .sz_i        (s1_sz_q),
    .l_phi_i     (l_phi),
    .l_theta_i   (l_theta),
    .normal_phi_i(s1_normal_phi_q),
    .phi_o       (phi),
    .theta_o     (theta)
  );

  // ---- Output register -------------------------------------------------------------------

  logic [A-1:0]         out_phi_q;
  logic [A-2:0]         out_theta_q;
  tmu_pkg::map_access_t out_access_q;

  // Data needs no reset: it is only observed while out_valid_q is set.
  always_ff @(posedge clk_i) begin
    if (s1_advance) begin
      out_phi_q    <= phi;
      out_theta_q  <= theta;
      out_access_q <= s1_bypass_q ? AccessBypass : s1_missed_q ? AccessMiss : AccessHit;
    end
  end

  assign out_valid_o  = out_valid_q;
  assign out_phi_o    = out_phi_q;
  assign out_theta_o  = out_theta_q;
  assign out_access_o = out_access_q;

  // Assertions run under Verilator (--assert); Yosys 0.23 cannot parse concurrent assertions
  // and defines SYNTHESIS.
`ifndef SYNTHESIS
  // The memory answers only a request that is outstanding.
  property p_resp_expected;
    @(posedge clk_i) disable iff (!rst_ni) map_resp_valid_i |-> fetching_q;
  endproperty
  a_resp_expected: assert property (p_resp_expected);
`endif

endmodule
