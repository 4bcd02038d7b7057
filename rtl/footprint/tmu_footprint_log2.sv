/// The footprint setup's base-2 logarithm (000 §10; golden footprint::log2_fixed in
/// golden/footprint/footprint.hpp): lg(x) = e 2^F + LOG[i] for x > 0, with e the index of the
/// leading one and i the bits below it rounded half up to TableBits bits (zero-padded when
/// fewer exist; i = 2^T when the rounding carries). Combinational.
///
/// LOG[i] = 2^F log2(1 + i / 2^T), i = 0 .. 2^T, T = TableBits, F = LogFracBits: the table
/// (2^T + 1 entries, LOG[0] = 0, LOG[2^T] = 2^F, hence F + 1 bits) is computed at elaboration
/// by table_entry(), a copy of golden's log2_table_entry (the binary logarithm digit
/// recurrence on y in Q1.30, F + 1 digits, rounded half up), so it follows the parameters.
/// lg(0) is "zero" (zero_o; value_o is 0 then).
///
/// The operand is normalised (shifted until its leading one is the top bit, T + 1 zeros
/// below it): the T + 1 bits under the leading one, plus one, halved, are the rounded index.
///
/// Example: T = 7, F = 8, x = 40 = 0b101000: e = 5, i = 0b01000 << 2 = 32, LOG[32] =
/// round(256 log2(1 + 32 / 128)) = 82, lg = 5 * 256 + 82 = 1362 (log2 40 = 5.32 = 1362.4/256).
/// x = 511 = 0b111111111, T = 7: e = 8, the 8 bits below are 0xFF, (0xFF + 1) >> 1 = 128 =
/// 2^T: LOG[128] = 256, lg = 9 * 256 (log2 511 = 8.997).
module tmu_footprint_log2 #(
  /// Bits of the operand (at least 2).
  parameter int unsigned XW          = 25,
  /// T: mantissa bits indexing the table, 1..10.
  parameter int unsigned TableBits   = 7,
  /// F: fraction bits of the logarithm, 1..12.
  parameter int unsigned LogFracBits = 8,
  /// Bits of e (derived) and of the result (derived: lg <= XW 2^F < 2^(VW)).
  localparam int unsigned EW = $clog2(XW),
  localparam int unsigned VW = $clog2(XW + 1) + LogFracBits
) (
  input  logic [XW-1:0] x_i,
  /// x_i == 0: the logarithm is minus infinity.
  output logic          zero_o,
  /// e, the index of the leading one: floor(log2 x_i) (0 when x_i is 0).
  output logic [EW-1:0] exp_o,
  /// lg(x_i), F fraction bits.
  output logic [VW-1:0] value_o
);

  localparam int unsigned T  = TableBits;
  localparam int unsigned F  = LogFracBits;
  localparam int unsigned EntryW = F + 1;

  if (XW < 2 || T < 1 || T > 10 || F < 1 || F > 12) begin : gen_check
    $error("tmu_footprint_log2: XW >= 2, TableBits 1..10, LogFracBits 1..12");
  end

  // golden footprint::log2_table_entry, step for step: y = 1 + index / 2^T in Q1.30;
  // F + 1 times: square (truncating to 30 fraction bits), a digit 1 halves y back into
  // [1, 2); then the F + 1 digits rounded half up to F.
  function automatic logic [EntryW-1:0] table_entry(input int unsigned index);
    logic [63:0]     y;
    logic [EntryW:0] digits;  // F + 1 digits, and room for the rounding carry
    integer          b;
    digits = '0;
    y = ((64'd1 << T) + 64'(index)) << (30 - T);
    for (b = 0; b <= F; b = b + 1) begin
      y = (y * y) >> 30;
      if (y >= (64'd2 << 30)) begin
        y      = y >> 1;
        digits = {digits[EntryW-1:0], 1'b1};
      end else begin
        digits = {digits[EntryW-1:0], 1'b0};
      end
    end
    table_entry = EntryW'((digits + 1'b1) >> 1);
  endfunction

  // The table, one constant per entry: LOG[0] .. LOG[2^T].
  logic [(2**T+1)*EntryW-1:0] table_bits;
  for (genvar i = 0; i <= 2**T; i++) begin : gen_table
    localparam logic [EntryW-1:0] Entry = table_entry(i);
    assign table_bits[i*EntryW +: EntryW] = Entry;
  end

  // Leading one, then the operand normalised so that it sits at the top: the T + 1 bits below
  // it (zeros shifted in when the operand has fewer), rounded half up to T bits.
  logic [EW-1:0]     e;
  logic [T:0]        below, index;
  logic [EntryW-1:0] entry;

  always_comb begin
    e = '0;
    for (int b = 0; b < XW; b++) begin
      if (x_i[b]) e = EW'(b);
    end
  end

  // {x, T + 1 zeros} shifted until the leading one is its top bit; the T + 1 bits below it.
  assign below      = (T + 1)'(({x_i, {(T + 1){1'b0}}} << (EW'(XW - 1) - e)) >> (XW - 1));
  // Half up: + 1, then drop the extra bit (2^T when every bit below is one).
  assign index      = (T + 1)'(((T + 2)'(below) + (T + 2)'(1)) >> 1);
  assign entry      = table_bits[32'(index)*EntryW +: EntryW];
  assign zero_o     = x_i == '0;
  assign exp_o      = e;
  assign value_o    = zero_o ? '0 : {e, {F{1'b0}}} + VW'(entry);

endmodule
