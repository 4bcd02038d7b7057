/// The normal encoder's angle table (001 §4.1, the paper's 128-entry LUT; golden
/// deflect::angle_index and deflect::angle_entry in golden/deflect/normal_encoder.hpp, the
/// specification): a ratio t = tan^2 of an angle to the angle in grid steps. Combinational.
///
/// Index: a floating index, because atan(sqrt(t)) is steepest at t = 0. With t16 = min(t,
/// 2^16 - 1), e = min(floor(clz16(t16) / 2), E - 1) (leading zero pairs: an even shift keeps
/// sqrt exact) and m the M bits of t16 << 2e below bit 16: index = e 2^M + m, E 2^M entries.
///
/// Entry (computed at elaboration by angle_entry(), the same double expression as golden, so
/// the table follows the parameters): the bucket is t_lo = m 2^-(M+2e) .. t_hi = (m + 1)
/// 2^-(M+2e) (exact in double: an integer over a power of two), the entry
///   round(((atan sqrt(t_lo) + atan sqrt(t_hi)) / 2) / delta),  delta = (pi / 2) / Q,
/// a step count 0 .. Q/2, Q = 2^(PhiBits-2).
///
/// Example (PhiBits 9, E 4, M 5): t = 0x0_4000 (a quarter, tan 26.6 degrees): clz16 = 1, e = 0,
/// m = 0x4000 >> 11 = 8, index 8: the bucket 8/32 .. 9/32, atan sqrt = 26.57 .. 27.94 degrees,
/// mean 27.25 degrees = 0.4757 rad / (pi / 256) = 38.8 -> 39 steps.
module tmu_normal_angle_lut #(
  /// A: bits of phi; Q = 2^(A-2) steps span a quarter turn. 6..12.
  parameter int unsigned PhiBits = 9,
  /// E: exponent levels of the index, 1..8 (1: the paper's linear index).
  parameter int unsigned LutExp  = 4,
  /// M: mantissa bits of the index, 2..10.
  parameter int unsigned LutMant = 5,
  /// Bits of an entry (derived): 0 .. Q/2 = 2^(A-3).
  localparam int unsigned KW = PhiBits - 2
) (
  /// t in UQ1.16: 0 .. 2^16 (1.0).
  input  logic [16:0]   t_i,
  /// The angle of t in steps, 0 .. Q/2.
  output logic [KW-1:0] k_o
);

  localparam int unsigned E       = LutExp;
  localparam int unsigned M       = LutMant;
  localparam int unsigned Q       = 1 << (PhiBits - 2);
  localparam int unsigned Entries = E << M;
  localparam int unsigned EW      = E > 1 ? $clog2(E) : 1;

  if (PhiBits < 6 || PhiBits > 12 || E < 1 || E > 8 || M < 2 || M > 10) begin : gen_check
    $error("tmu_normal_angle_lut: PhiBits 6..12, LutExp 1..8, LutMant 2..10");
  end

  // golden angle_entry, the same double operations in the same order (Yosys 0.23 accepts no
  // real variables, hence one expression): m and m + 1 over 2^(M+2e) (exact: golden's
  // ldexp), atan of their square roots, the mean over the step, rounded half up. pi is the
  // literal of std::numbers::pi (strtod gives the same double).
  function automatic integer angle_entry(input integer index);
    angle_entry = $rtoi($floor(
        (($atan($sqrt((index % (1 << M)) * 1.0 / (1 << (M + 2 * (index >> M))))) +
          $atan($sqrt(((index % (1 << M)) + 1) * 1.0 / (1 << (M + 2 * (index >> M)))))) / 2.0) /
        ((3.141592653589793 / 2.0) / Q) + 0.5));
  endfunction

  // The table, one constant per entry (two loops: Verilator unrolls at most 1024 iterations).
  logic [Entries*KW-1:0] table_bits;
  for (genvar ie = 0; ie < E; ie++) begin : gen_level
    for (genvar im = 0; im < (1 << M); im++) begin : gen_entry
      localparam int unsigned Index = (ie << M) + im;
      localparam logic [KW-1:0] Entry = KW'(angle_entry(Index));
      assign table_bits[Index*KW +: KW] = Entry;
    end
  end

  // The index: t16 saturated, its leading zero pairs (at most E - 1), the M bits below bit 16
  // of t16 shifted by two per pair.
  logic [15:0]    t16;
  logic [EW-1:0]  e;
  logic [M-1:0]   m;
  integer         index;

  assign t16 = t_i[16] ? 16'hFFFF : t_i[15:0];

  // Smallest pair j (bits 15-2j, 14-2j) holding a one, E - 1 when none below E - 1 does.
  always_comb begin
    e = EW'(E - 1);
    for (int j = E - 1; j > 0; j--) begin  // pair j - 1, downwards: the smallest one wins
      if (t16[17-2*j -: 2] != 2'b00) e = EW'(j - 1);
    end
  end

  assign m     = M'(16'(t16 << {e, 1'b0}) >> (16 - M));
  assign index = (32'(e) << M) | 32'(m);
  assign k_o   = table_bits[index*KW +: KW];

endmodule
