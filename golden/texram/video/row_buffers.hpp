// Page-row buffers and the write arbiter of the video path (docs/video.md), a cycle model at
// the memory clock: one access per cycle (30 ns, 000 §5), a page fault costs a second cycle.
//
// The mipmap generator's cell writes are collected per bank into row buffers, each holding one
// aligned segment of `segment_cells` cells of one DRAM page (512 cells) and a mask of the cells
// written. A buffer becomes ready when every cell of its segment is written, or when its frame
// ends (flush). A ready buffer is written to its bank in one access (masked). The arbiter, each
// cycle not taken by the second cycle of a faulting write:
//   1. the oldest ready buffer (in order of becoming ready) whose frame is not held (the swap
//      barrier, video_map.hpp) is written if the sampler does not want the cycle, or if it has
//      waited `max_wait` (L) cycles or more: then it takes the cycle and the sampler loses it;
//   2. otherwise the sampler, if it wants the cycle, gets it.
// Before 1, a read of the line above (request_read) goes first under the same rule with its own
// bound `read_wait` (default 0).
// Pages: each bank keeps the page last written open; a sampler access is taken to close every
// bank's page (pessimistic: the sampler reads other maps), so a write after a sampler access
// faults. A cell write that finds no free buffer in its bank is lost and counted (the source
// cannot be stalled); the sizing in docs/video.md makes that never happen at the stated rates,
// and the tests assert it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "texram/page_model.hpp"
#include "texram/texture.hpp"

namespace tmu::texram::video {

struct ArbiterConfig {
  uint32_t segment_cells = 512;  // a buffer: an aligned part of a page, a power of two 1..512
  int buffers_per_bank = 8;      // row buffers of each bank (sized in docs/video.md)
  uint32_t max_wait = 64;        // L: cycles a ready buffer waits for a free cycle at most
  uint32_t read_wait = 0;        // cycles a read (the line above) waits for a free cycle at most
  bool direct = false;           // no buffers: every cell written at once (the reference)
};

struct ArbiterStats {
  uint64_t cycles = 0;
  uint64_t sampler_wanted = 0;    // cycles the sampler wanted the memory
  uint64_t sampler_granted = 0;   // ... and got it
  uint64_t sampler_lost = 0;      // ... and did not (a write had it): wanted - granted
  uint64_t write_accesses = 0;    // buffers written
  uint64_t write_cycles = 0;      // cycles the writes took (accesses + page faults)
  uint64_t page_faults = 0;       // write accesses that faulted
  uint64_t cells_in = 0;          // cell writes collected
  uint64_t cells_written = 0;     // cells the write accesses stored
  uint64_t lost_writes = 0;       // cell writes that found no free buffer
  uint64_t read_accesses = 0;     // segment reads (interlaced field 2's line above)
  uint64_t read_cycles = 0;       // cycles they took (accesses + page faults)
  uint64_t read_faults = 0;       // read accesses that faulted
  uint64_t max_read_latency = 0;  // most cycles a read waited from its request to its access
  uint64_t forced_writes = 0;  // writes and reads that waited max_wait and took the sampler's cycle
  uint64_t max_latency = 0;    // most cycles a buffer waited from ready to its access
  uint64_t min_latency = ~uint64_t{0};  // fewest (no write yet: all ones)
  uint64_t latency_sum = 0;             // for the mean: latency_sum / write_accesses
  size_t max_ready = 0;                 // most buffers ready at once
  size_t max_busy_bank = 0;             // most buffers not free in one bank at once (high-water)
  size_t max_busy_total = 0;            // most buffers not free in all banks at once
  double mean_latency() const {
    return write_accesses ? static_cast<double>(latency_sum) / static_cast<double>(write_accesses)
                          : 0.0;
  }
};

// A frame's tag in the row buffers, as the hardware keeps it (formats::kVideoTag, 16 bits):
// frame n >= 1 of a video map is tag 1 + (n - 1) mod 0xFFFE, so 1 .. 0xFFFE and then 1 again;
// 0xFFFF (kTagNone) names no frame, the swap barrier lifted. Tags compare as serial numbers,
// a - b taken modulo 2^16 as a signed number: the frames in the rows at once are a few (the
// one held for its swap and the next, or a dropped one), far fewer than half the tags.
inline constexpr uint32_t kTagNone = 0xFFFF;
constexpr uint32_t frame_tag(uint64_t frame) {
  return frame == 0 ? 0 : static_cast<uint32_t>((frame - 1) % 0xFFFE) + 1;
}
// Tag a is tag b or a later frame's.
constexpr bool tag_not_before(uint32_t a, uint32_t b) { return ((a - b) & 0xFFFFu) < 0x8000u; }

class RowBuffers {
 public:
  // `memory` is the chip's banks the writes go to. Throws std::invalid_argument for a segment
  // that is not a power of two up to 512 or fewer than one buffer per bank.
  RowBuffers(const ArbiterConfig& config, BankImage& memory);

  const ArbiterConfig& config() const { return config_; }

  // One cell write of frame `tag` (frame_tag: tags ascend frame by frame, and wrap).
  void put(unsigned bank, uint32_t address, uint8_t value, uint32_t tag);
  // Frame `tag` ends: every buffer collecting its cells becomes ready.
  void flush(uint32_t tag);
  // Writes of frames after frame `tag` wait (the swap barrier); kTagNone holds none.
  void hold_after(uint32_t tag) { hold_after_ = tag; }
  // No buffer holds a cell of the frame the barrier names (its tag): that frame is in the
  // memory, and the video unit may swap it in. True when no frame is named.
  bool held_frame_written() const { return buffers_of(hold_after_) == 0; }
  // Buffers holding cells of frame `tag`, in any state but free (0: all in memory).
  size_t buffers_of(uint32_t tag) const;
  size_t buffers_busy() const;  // No buffer ready or being written and no read waiting (collecting
                                // buffers may remain).
  bool idle() const { return ready_.empty() && reads_.empty() && busy_ == 0; }

  // A read of segment `segment` of `bank` into the shift registers 826 (the line above for
  // interlaced field 2): one access, a second cycle on a page fault. Reads go before the ready
  // buffers (they have a deadline, the line they serve; writes have buffers), in request order,
  // in a cycle the sampler does not want or once they have waited `read_wait` cycles (default
  // 0: at once). Its data are the cells as the writes so far leave them at the access: the
  // memory's, with those the access's mask names taken from its data (the newest row buffer
  // holding each). Returns the number of reads requested so far; reads complete in request
  // order.
  uint64_t request_read(unsigned bank, uint32_t segment);
  uint64_t reads_completed() const { return reads_completed_; }

  // One memory cycle. Returns whether the sampler got the cycle (false when it did not want it).
  bool cycle(bool sampler_wants);

  // What the last cycle() started: a write of a buffer or a read of a segment (the block
  // driver of the video_rows co-simulation compares every access with the RTL's).
  struct Access {
    enum class Kind : uint8_t { kNone, kWrite, kRead } kind = Kind::kNone;
    unsigned bank = 0;
    uint32_t segment = 0;
    bool fault = false;
    // A write: the cells written (segment_cells of them) and the buffer's cells. A read: the
    // cells a row buffer holds (the newest buffer's), which the read's data take instead of the
    // memory's. A cell not in the mask: 0.
    std::vector<bool> mask;
    std::vector<uint8_t> data;
    uint64_t wait = 0;  // cycles from ready (a write) or request (a read) to the access
  };
  const Access& last_access() const { return last_; }
  // A new bound L and read bound, effective from the next cycle (the buffers stay).
  void set_waits(uint32_t max_wait, uint32_t read_wait) {
    config_.max_wait = max_wait;
    config_.read_wait = read_wait;
  }
  size_t reads_pending() const { return reads_.size(); }

  const ArbiterStats& stats() const { return stats_; }

 private:
  enum class State : uint8_t { kFree, kCollecting, kReady, kWriting };
  struct Buffer {
    State state = State::kFree;
    unsigned bank = 0;
    uint32_t segment = 0;  // address / segment_cells
    uint32_t tag = 0;
    uint64_t ready_cycle = 0;
    uint32_t count = 0;  // cells written
    std::vector<uint8_t> data;
    std::vector<bool> valid;
  };
  Buffer* collecting(unsigned bank, uint32_t segment, uint32_t tag);
  // The newest buffer (the latest tag, then the last) not free holding cell i of the segment.
  const Buffer* newest_holding(unsigned bank, uint32_t segment, uint32_t i) const;
  void make_ready(size_t id);
  void write_access(size_t id);
  void read_access();
  void note_busy();

  ArbiterConfig config_;
  BankImage& memory_;
  std::vector<Buffer> buffers_;  // bank b's are b * buffers_per_bank ...
  std::deque<size_t> ready_;     // in order of becoming ready
  std::array<std::optional<uint32_t>, 8> open_page_{};
  uint32_t hold_after_ = kTagNone;
  size_t writing_ = 0;    // the buffer of a write in its second (page fault) cycle
  bool reading_ = false;  // the access in progress is a read
  struct Read {
    unsigned bank = 0;
    uint32_t segment = 0;
    uint64_t request_cycle = 0;
  };
  std::deque<Read> reads_;
  uint64_t reads_requested_ = 0, reads_completed_ = 0;
  int busy_ = 0;  // cycles left of that write
  ArbiterStats stats_;
  Access last_;
};

}  // namespace tmu::texram::video
