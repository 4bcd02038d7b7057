// Video mapping (000 §11-12; docs/video.md): the video port's stream through the mipmap
// generator (one MipgenStream per plane) into the chip's memory, double buffered.
//
// A video map owns two buffers in the shared memory, each one map of the format's layout:
// buffer 0 at `base`, buffer 1 at base + bank_cells rounded up to a page (512 cells). The DRF
// `drf`'s base field names the front buffer, the one the sampler reads; frames are written to the
// other, the back buffer. When a frame is complete and its last cell has reached the memory (every
// page-row buffer holding it written), the video unit writes the DRF's base field itself (a
// chip-side swap, through the DRF write port's apply(), between two pixels like every DRF write):
// the sampler only ever reads complete frames. Until that swap the next frame's writes, which go to
// the old front buffer, are held in the row buffers (the swap barrier: RowBuffers::hold_after).
//
// Interlaced field-2 items need `above`, the level-0 texel of the line above: the line is read
// into the shift registers 826 a line ahead, as segment reads through the arbiter
// (RowBuffers::request_read; line 0 at the start of field 1's last line, line y + 1 at the
// start of field-2 line y). The shift registers hold two lines (line a in slot (a / 2) mod 2, so
// the line being read never overwrites the line in use); a read's cells of its line enter them
// at the access, as RowBuffers gives them (a row buffer's cell, else the memory's). A two-line
// frame's line 0 is taken into them as it arrives. A line that begins before its reads are done
// is counted (late_reads) and takes what the registers hold. A dropped frame (video_port.hpp) has
// written part of the back buffer; it is never shown, and the next frame, to the same buffer,
// writes every cell again. A frame complete while the previous one still waits for its swap
// (the memory cannot keep up) is not shown either: it is counted as an overrun, and the next
// frame goes to the same buffer.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

#include "texram/chip/drf.hpp"
#include "texram/layout.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/texture.hpp"
#include "texram/video/row_buffers.hpp"
#include "texram/video/video_port.hpp"

namespace tmu::texram::video {

struct VideoMapConfig {
  VideoFormat format;
  uint32_t base = 0;  // buffer 0's first cell in every bank
  int drf = 1;        // the DRF (1..7) whose base shows the front buffer
  ArbiterConfig arbiter;
  // The reads' memory data come from the caller (capture()), as in a unit whose memory answers
  // later; by default from the model's own memory at the access.
  bool external_reads = false;
  // Buffer 1's first cell; by default the next page boundary after buffer 0 (buffer_stride).
  // The buffers must not overlap.
  std::optional<uint32_t> base1 = std::nullopt;
};

// One frame the port began.
struct FrameRecord {
  uint64_t tag = 0;  // frames begun so far, 1 for the first (the rows' tag: frame_tag(tag))
  int buffer = 0;    // the buffer it was written to
  bool complete = false;
  bool dropped = false;
  uint64_t begin_cycle = 0, end_cycle = 0;  // first item, last item (or the drop)
  std::optional<uint64_t> swap_cycle;       // the cycle after which the sampler reads it
};

class VideoMap {
 public:
  // Throws std::invalid_argument for a bad format, DRF or arbiter configuration, or buffers that
  // end beyond the chip's kBankCells.
  explicit VideoMap(const VideoMapConfig& config);

  const VideoMapConfig& config() const { return config_; }
  const Geometry& geometry() const { return geometry_; }
  uint32_t buffer_base(int buffer) const {
    if (buffer == 0) return config_.base;
    return config_.base1 ? *config_.base1 : config_.base + buffer_stride(geometry_);
  }
  // Buffer 1 follows buffer 0 at the next page boundary: a buffer's bank_cells rounded up to a
  // DRAM page (512 cells), so that both buffers' lines fall on pages alike.
  static uint32_t buffer_stride(const Geometry& g) { return page_up(g.bank_cells()); }

  // One item of the port, arriving in the current cycle.
  void receive(const VideoItem& item);
  // New bounds L and read_wait, effective from the next cycle.
  void set_waits(uint32_t max_wait, uint32_t read_wait) {
    config_.arbiter.max_wait = max_wait;
    config_.arbiter.read_wait = read_wait;
    rows_.set_waits(max_wait, read_wait);
  }
  // One memory cycle; returns whether the sampler got it. A swap due at its end is applied.
  bool cycle(bool sampler_wants);
  // external_reads: the memory's cells of the read the last cycle() started
  // (row_buffers().last_access(), segment_cells of them), before the next item.
  void capture(const std::vector<uint8_t>& memory_cells);
  // A swap was applied at the end of the last cycle().
  bool swapped() const { return swapped_; }

  // The DRFs as the swaps leave them; drfs()[drf - 1].base is the front buffer's base.
  const chip::DrfFile& drfs() const { return drfs_; }
  int front_buffer() const { return front_; }
  // The tag of the frame the front buffer holds (0: none yet).
  uint64_t front_tag() const { return front_tag_; }
  bool swap_pending() const { return pending_.has_value(); }
  const std::vector<FrameRecord>& frames() const { return frames_; }
  const BankImage& memory() const { return memory_; }
  const RowBuffers& row_buffers() const { return rows_; }
  const VideoReceiver& receiver() const { return receiver_; }
  uint64_t cycles() const { return rows_.stats().cycles; }
  // Interlaced field-2 lines whose line above had not been read into the shift registers when
  // the line began (0 at every rate the tests run).
  uint64_t late_reads() const { return late_reads_; }
  // Frames complete while the previous one waited for its swap (not shown).
  uint64_t overruns() const { return overruns_; }

  // Plane `plane`'s texel (x, y) of `level` in buffer `buffer`, read from the memory.
  uint8_t read(int buffer, int level, uint32_t x, uint32_t y, int plane) const;
  // Every level of plane `plane` of buffer `buffer` as the memory holds it.
  Pyramid8 read_pyramid(int buffer, int plane) const;

 private:
  void begin_frame();
  void end_frame(bool complete);
  // Requests the reads of level-0 line `above` of the frame under way, for field-2 line `line`.
  void read_line_above(uint32_t above, uint32_t line);
  // The shift registers' cell of level-0 line `line`, column x, plane p (line even).
  uint8_t& above_cell(uint32_t line, uint32_t x, int p);
  // Level-0 line `line`'s first cell in its banks, relative to the buffer's base.
  uint32_t line_start(uint32_t line) const;
  uint32_t line_cells() const;  // cells of a level-0 line in each of its two banks

  VideoMapConfig config_;
  Geometry geometry_;
  BankImage memory_;
  RowBuffers rows_;
  VideoReceiver receiver_;
  chip::DrfFile drfs_{};
  std::vector<MipgenStream> streams_;  // one per plane, for the frame under way
  std::vector<CellWrite> writes_;
  std::vector<FrameRecord> frames_;
  int front_ = 0;   // buffer the DRF shows
  int newest_ = 0;  // buffer of the newest complete frame (shown or pending)
  uint64_t front_tag_ = 0;
  std::optional<size_t> pending_;       // frames_ index of the complete frame awaiting its swap
  std::vector<uint64_t> reads_needed_;  // per line: reads that must be complete at its start
  uint64_t late_reads_ = 0;
  uint64_t overruns_ = 0;
  bool swapped_ = false;
  // The shift registers: slot (line / 2) mod 2, column parity; line_cells() cells each.
  std::array<std::vector<uint8_t>, 4> above_;
  struct LineRead {
    uint32_t line = 0;  // the level-0 line it reads
    uint32_t base = 0;  // the buffer's base
  };
  std::deque<LineRead> line_reads_;  // requested, not yet accessed, in order
};

// Cycles at which the sampler wants the memory.
enum class SamplerPattern : uint8_t { kNone, kFull, kRandom };

// Texels per memory cycle, num / den.
struct VideoRate {
  uint64_t num = 0, den = 1;
};
inline constexpr uint64_t kCycleNs = 30;  // one access per cycle (000 §5, page_model.hpp)
// A w x h video at `fps` frames per second, back to back (no blanking), in texels per 30 ns.
constexpr VideoRate video_rate(uint64_t w, uint64_t h, uint64_t fps) {
  return {w * h * fps * kCycleNs, 1'000'000'000};
}

struct RunOptions {
  VideoRate rate;
  SamplerPattern sampler = SamplerPattern::kFull;
  uint32_t random_percent = 50;  // kRandom: the sampler wants a cycle with this probability
  uint64_t seed = 1;             // kRandom
  uint64_t drain_cycles = 0;     // cycles run after the last item (0: until every swap is done)
  // Called after every cycle with whether the sampler got it.
  std::function<void(const VideoMap&, bool granted)> on_cycle;
};

// The arrivals of n items at a rate, cycle by cycle: in each cycle the accumulator gains
// rate.num, and each whole texel (rate.den) it holds is an item arriving, arrive(i) for item i,
// before cycle(); until the cycle of the last item. run()'s schedule, and the video unit's
// figure workload's (tb/blocks/video_unit).
void at_rate(size_t n, VideoRate rate, const std::function<void(size_t)>& arrive,
             const std::function<void()>& cycle);

// Feeds `items` to `map` at the rate (at_rate: an item arrives in cycle t when the rate's
// accumulator passes a whole texel), one memory cycle at a time, then runs until the last frame is
// swapped in and every row buffer is written (or drain_cycles). Returns the cycles run.
uint64_t run(VideoMap& map, const std::vector<VideoItem>& items, const RunOptions& options);

}  // namespace tmu::texram::video
