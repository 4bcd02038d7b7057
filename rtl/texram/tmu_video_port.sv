/// The TEXRAM's serial video port receiver (000 §11, Fig. 8 808; docs/video.md): one item per
/// level-0 texel, each checked against the place it must fill. Bit-exact with the golden
/// texram::video::VideoReceiver (golden/texram/video/video_port.hpp), which defines the flags
/// of a place, the source order and what a malformed stream does.
///
/// Input: an item's four flags (bit 0 first of frame, 1 first of field, 2 first of line,
/// 3 field 2) and its texel's bytes. Output, one per item: whether the item is texel
/// (out_x_o, out_y_o) of the frame under way, whether it starts or ends a frame, whether the
/// frame under way was dropped before it, its error, and its texel with the planes beyond
/// the format's set to 0.
///
/// The receiver keeps the place the next item must fill (x_q, y_q) while a frame is under way
/// (in_frame_q). An item whose flags are those of its place is accepted and the place
/// advances (progressive: raster order; interlaced: field 1's even lines, then field 2's odd
/// lines). An item whose flags differ drops the frame (counted) and is then taken as a
/// possible start: a first-of-frame item of field 1 (flags 7) starts a new frame at (0, 0);
/// one flagged field 2 is a field-order error (counted); any other item is discarded
/// (counted) until a frame starts. The source cannot be stalled by a malformed stream: every
/// item gives one output in one cycle.
///
/// Configuration (cfg_*) is quasi-static: a driver writes it between frames. A format that
/// differs from the one registered (fmt_q) drops a frame under way (counted), as
/// VideoReceiver::set_format does; the input is not ready in that cycle.
///
/// Example: a 2 x 4 interlaced frame arrives as (0, 0) flags 7, (1, 0) 0, (0, 2) 4, (1, 2) 0,
/// (0, 1) 14, (1, 1) 8, (0, 3) 12, (1, 3) 8; the last is out_frame_end_o.
module tmu_video_port (
  input  logic                    clk_i,
  input  logic                    rst_ni,

  /// Frame format: log2 of the level-0 width and height (0..MaxMipLog2), interlaced source,
  /// four planes (else one, in 31:24).
  input  tmu_pkg::mip_log2_t      cfg_log2_w_i,
  input  tmu_pkg::mip_log2_t      cfg_log2_h_i,
  input  logic                    cfg_interlaced_i,
  input  logic                    cfg_four_planes_i,

  /// Items: flags and the texel's bytes.
  input  logic                    in_valid_i,
  output logic                    in_ready_o,
  input  tmu_pkg::video_flags_t   in_flags_i,
  input  tmu_pkg::video_texel_t   in_texel_i,

  /// What the receiver makes of each item.
  output logic                    out_valid_o,
  input  logic                    out_ready_i,
  output logic                    out_accepted_o,
  output tmu_pkg::mip_coord_t     out_x_o,
  output tmu_pkg::mip_coord_t     out_y_o,
  output logic                    out_frame_start_o,
  output logic                    out_frame_end_o,
  output logic                    out_dropped_o,
  output tmu_pkg::video_error_t   out_error_o,
  output tmu_pkg::video_texel_t   out_texel_o,

  /// ReceiverStats, 32-bit wrapping counters.
  output tmu_pkg::stat_count_t    stat_items_o,
  output tmu_pkg::stat_count_t    stat_frames_complete_o,
  output tmu_pkg::stat_count_t    stat_frames_dropped_o,
  output tmu_pkg::stat_count_t    stat_items_discarded_o,
  output tmu_pkg::stat_count_t    stat_field_order_errors_o
);

  localparam int unsigned CoordW = tmu_pkg::MipCoordW;
  localparam int unsigned FmtW   = 2 * tmu_pkg::MipLog2W + 2;
  localparam int unsigned StatW  = tmu_pkg::StatCountW;
  localparam tmu_pkg::video_flags_t FrameStart = 4'b0001;
  localparam tmu_pkg::video_flags_t FieldStart = 4'b0010;
  localparam tmu_pkg::video_flags_t LineStart  = 4'b0100;
  localparam tmu_pkg::video_flags_t Field2     = 4'b1000;
  localparam tmu_pkg::video_error_t ErrNone       = 2'd0;
  localparam tmu_pkg::video_error_t ErrBadFlags   = 2'd1;
  localparam tmu_pkg::video_error_t ErrFieldOrder = 2'd2;

  // ---- The format and its change ----------------------------------------------------------

  logic [FmtW-1:0] fmt, fmt_q;
  logic            fmt_changed;
  logic [CoordW:0] width, height;
  logic            fields;  // interlaced order in effect: interlaced and more than one line

  assign fmt         = {cfg_log2_w_i, cfg_log2_h_i, cfg_interlaced_i, cfg_four_planes_i};
  assign fmt_changed = fmt != fmt_q;
  assign width       = (CoordW + 1)'(1) << cfg_log2_w_i;
  assign height      = (CoordW + 1)'(1) << cfg_log2_h_i;
  assign fields      = cfg_interlaced_i && cfg_log2_h_i != '0;

  // ---- The place the next item must fill ----------------------------------------------------

  logic                in_frame_q, in_frame_d;
  tmu_pkg::mip_coord_t x_q, x_d, y_q, y_d;
  tmu_pkg::video_flags_t expected;  // the flags of (x_q, y_q)
  logic [CoordW:0]     x_next, y_next;

  always_comb begin
    expected = '0;
    if (x_q == '0) expected |= LineStart;
    if (x_q == '0 && (y_q == '0 || (fields && y_q == CoordW'(1)))) expected |= FieldStart;
    if (x_q == '0 && y_q == '0) expected |= FrameStart;
    if (fields && y_q[0]) expected |= Field2;
  end

  // ---- One item ------------------------------------------------------------------------------

  logic                  fire;
  logic                  match;     // in a frame, the flags of its place
  logic                  drop;      // in a frame, other flags: the frame is dropped
  logic                  order_err; // taken as a start: first of frame in field 2
  logic                  starts;    // taken as a start: flags 7
  logic                  last;      // the accepted texel ends the frame
  logic                  accepted;
  tmu_pkg::mip_coord_t   acc_x, acc_y;
  tmu_pkg::video_error_t error;

  assign in_ready_o = (!out_valid_o || out_ready_i) && !fmt_changed;
  assign fire       = in_valid_i && in_ready_o;
  assign match      = in_frame_q && in_flags_i == expected;
  assign drop       = in_frame_q && !match;
  assign order_err  = !match && (in_flags_i & (FrameStart | Field2)) == (FrameStart | Field2);
  assign starts     = !match && in_flags_i == (FrameStart | FieldStart | LineStart);
  assign accepted   = match || starts;
  assign acc_x      = match ? x_q : '0;
  assign acc_y      = match ? y_q : '0;
  // The place accepted is the frame's last: (width - 1, height - 1).
  assign last       = accepted && {1'b0, acc_x} + (CoordW + 1)'(1) == width &&
                      {1'b0, acc_y} + (CoordW + 1)'(1) == height;
  assign error      = order_err ? ErrFieldOrder : (drop ? ErrBadFlags : ErrNone);

  // The place after an accepted texel that does not end its frame: the next texel of its
  // line, else the next line of its field, or field 2's first line after field 1's last.
  assign x_next = {1'b0, acc_x} + (CoordW + 1)'(1);
  assign y_next = {1'b0, acc_y} + (fields ? (CoordW + 1)'(2) : (CoordW + 1)'(1));

  always_comb begin
    in_frame_d = in_frame_q;
    x_d        = x_q;
    y_d        = y_q;
    if (fire) begin
      in_frame_d = accepted && !last;
      if (accepted && !last) begin
        if (x_next < width) begin
          x_d = x_next[CoordW-1:0];
          y_d = acc_y;
        end else begin
          x_d = '0;
          y_d = (fields && y_next == height) ? CoordW'(1) : y_next[CoordW-1:0];
        end
      end
    end else if (fmt_changed) begin
      in_frame_d = 1'b0;
    end
  end

  // ---- Counters -----------------------------------------------------------------------------

  tmu_pkg::stat_count_t items_q, complete_q, dropped_q, discarded_q, order_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_frame_q  <= 1'b0;
      x_q         <= '0;
      y_q         <= '0;
      fmt_q       <= '0;
      out_valid_o <= 1'b0;
      items_q     <= '0;
      complete_q  <= '0;
      dropped_q   <= '0;
      discarded_q <= '0;
      order_q     <= '0;
    end else begin
      in_frame_q <= in_frame_d;
      x_q        <= x_d;
      y_q        <= y_d;
      fmt_q      <= fmt;
      if (fire) out_valid_o <= 1'b1;
      else if (out_ready_i) out_valid_o <= 1'b0;
      if (fire) begin
        items_q     <= items_q + StatW'(1);
        complete_q  <= complete_q + StatW'(last);
        dropped_q   <= dropped_q + StatW'(drop);
        discarded_q <= discarded_q + StatW'(!accepted);
        order_q     <= order_q + StatW'(order_err);
      end else if (fmt_changed && in_frame_q) begin
        dropped_q <= dropped_q + StatW'(1);
      end
    end
  end

  // The output register: data without reset, loaded with each item.
  always_ff @(posedge clk_i) begin
    if (fire) begin
      out_accepted_o    <= accepted;
      out_x_o           <= acc_x;
      out_y_o           <= acc_y;
      out_frame_start_o <= starts;
      out_frame_end_o   <= last;
      out_dropped_o     <= drop;
      out_error_o       <= error;
      out_texel_o       <= cfg_four_planes_i ? in_texel_i : {in_texel_i[31:24], 24'h0};
    end
  end

  assign stat_items_o              = items_q;
  assign stat_frames_complete_o    = complete_q;
  assign stat_frames_dropped_o     = dropped_q;
  assign stat_items_discarded_o    = discarded_q;
  assign stat_field_order_errors_o = order_q;

endmodule
