#include "blocks/video_rows/video_rows_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>

#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/video_rows_sc.hpp"
#include "rtl_models_video_rows.hpp"

TMU_DESCRIBE_SC(video_rows)

namespace tmu::tb {
namespace fmts = tmu::formats;
namespace video = texram::video;
using D = desc::video_rows;

texram::video::ArbiterConfig video_rows_config(uint32_t max_wait, uint32_t read_wait) {
  video::ArbiterConfig c;
  c.segment_cells = 8;
  c.buffers_per_bank = 8;
  c.max_wait = max_wait;
  c.read_wait = read_wait;
  return c;
}

namespace {

constexpr uint32_t kCells = 8;
constexpr uint64_t kWaitMax = 0xFFFF;  // the RTL's waits saturate at 16 bits

// The golden buffers over a run: what every model of the block (and the stimulus, which keeps
// the read queue within its 8 entries, and the coverage) steps.
class Rows {
 public:
  Rows()
      : memory_(make_memory()),
        rows_(std::make_unique<video::RowBuffers>(video_rows_config(64, 0), memory_)) {}
  void configure(const Txn& cfg) {
    rows_->set_waits(static_cast<uint32_t>(cfg.f[D::cfg_max_wait]),
                     static_cast<uint32_t>(cfg.f[D::cfg_read_wait]));
  }
  // One stimulus item; a cycle item's output in *out.
  void step(const Txn& item, Txn* out) {
    const auto op = static_cast<int>(item.f[0]);
    if (op == D::op_put) {
      rows_->put(
          static_cast<unsigned>(item.f[D::put_bank]), static_cast<uint32_t>(item.f[D::put_addr]),
          static_cast<uint8_t>(item.f[D::put_value]), static_cast<uint32_t>(item.f[D::put_tag]));
    } else if (op == D::op_flush) {
      rows_->flush(static_cast<uint32_t>(item.f[D::flush_tag]));
    } else if (op == D::op_hold) {
      rows_->hold_after(static_cast<uint32_t>(item.f[D::hold_tag]));
    } else if (op == D::op_read) {
      if (rows_->reads_pending() >= kVideoRowsReadQueue) {
        throw std::runtime_error(fmt::format(
            "video_rows: a read requested with {} reads pending (the read queue holds {})",
            rows_->reads_pending(), kVideoRowsReadQueue));
      }
      rows_->request_read(static_cast<unsigned>(item.f[D::read_bank]),
                          static_cast<uint32_t>(item.f[D::read_addr]) / kCells);
    } else if (op == D::op_cycle) {
      const bool granted = rows_->cycle(item.f[D::cycle_sampler] != 0);
      if (out == nullptr) return;
      const video::RowBuffers::Access& a = rows_->last_access();
      *out = Txn{};
      out->f[D::out_granted] = granted;
      out->f[D::out_drained] = rows_->held_frame_written();
      if (a.kind == video::RowBuffers::Access::Kind::kNone) return;
      out->f[D::out_write] = a.kind == video::RowBuffers::Access::Kind::kWrite;
      out->f[D::out_read] = a.kind == video::RowBuffers::Access::Kind::kRead;
      out->f[D::out_fault] = a.fault;
      out->f[D::out_bank] = a.bank;
      out->f[D::out_addr] = a.segment * kCells;
      for (size_t i = 0; i < a.mask.size(); ++i) {
        out->f[D::out_mask + i] = a.mask[i];
        out->f[D::out_data + i] = a.data[i];
      }
      out->f[D::out_wait] = std::min(a.wait, kWaitMax);
    } else {
      throw std::runtime_error(fmt::format("video_rows: an item of op {}", op));
    }
  }
  const video::RowBuffers& rows() const { return *rows_; }

 private:
  static texram::BankImage make_memory() {
    texram::BankImage m;
    for (auto& bank : m) bank.assign(size_t{1} << fmts::kBankAddr.width(), 0);
    return m;
  }
  texram::BankImage memory_;
  std::unique_ptr<video::RowBuffers> rows_;
};

class Golden : public Model {
 public:
  void configure(const Txn& cfg) override { rows_.configure(cfg); }
  void step(const Txn& item, Sink& sink) override {
    Txn out;
    rows_.step(item, &out);
    if (static_cast<int>(item.f[0]) == D::op_cycle) sink.output(out);
  }
  Counters counters() const override {
    const video::ArbiterStats& s = rows_.rows().stats();
    const auto c32 = [](uint64_t v) { return v & 0xFFFF'FFFFu; };  // the RTL's 32-bit registers
    return {{"cells_in", c32(s.cells_in)},
            {"lost_writes", c32(s.lost_writes)},
            {"forced", c32(s.forced_writes)},
            {"max_ready", c32(s.max_ready)},
            {"max_busy_bank", c32(s.max_busy_bank)}};
  }

 private:
  Rows rows_;
};

int uniform(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

Txn cfg_item(uint32_t max_wait, uint32_t read_wait) {
  return channel_item(D::table(), "cfg", {max_wait, read_wait});
}
Txn put_item(unsigned bank, uint32_t addr, uint8_t value, uint64_t tag) {
  return channel_item(D::table(), "put", {bank, addr, value, tag});
}
Txn flush_item(uint64_t tag) { return channel_item(D::table(), "flush", {tag}); }
Txn hold_item(uint64_t tag) { return channel_item(D::table(), "hold", {tag}); }
Txn read_item(unsigned bank, uint32_t addr) {
  return channel_item(D::table(), "read", {bank, addr});
}
Txn cycle_item(bool sampler) { return channel_item(D::table(), "cycle", {sampler ? 1u : 0u}); }

constexpr uint64_t kHoldNone = 0xFFFF;

// A run of frames as the video unit makes it, kept within the read queue by a mirror of the
// golden buffers.
class Stimulus {
 public:
  explicit Stimulus(std::vector<Txn>& items) : items_(items) {}
  void add(const Txn& t) {
    if (D::table().is_cfg(t)) {
      rows_.configure(t);
    } else {
      rows_.step(t, nullptr);
    }
    items_.push_back(t);
  }
  void cycles(int n, double sampler_rate, std::mt19937_64& rng) {
    for (int i = 0; i < n; ++i) {
      add(cycle_item(static_cast<double>(rng() % 1000) < sampler_rate * 1000.0));
    }
  }
  bool read(unsigned bank, uint32_t addr) {
    if (rows_.rows().reads_pending() >= kVideoRowsReadQueue) return false;
    add(read_item(bank, addr));
    return true;
  }
  // One random frame, the n-th (its tag video::frame_tag(n), wrapping after 0xFFFE): rows over
  // pages 0..3 of random banks, full or partial, their cells shuffled, memory cycles between
  // them at the sampler rate, now and then a read; then the frame's flush and a tail of cycles.
  void frame(uint64_t n, std::mt19937_64& rng) {
    const uint32_t tag = video::frame_tag(n);
    const double rate = std::array<double, 5>{0.0, 0.3, 0.7, 0.95, 1.0}[rng() % 5];
    const int rows = uniform(rng, 1, rng() % 8 == 0 ? 40 : 12);
    std::vector<std::array<uint32_t, 3>> cells;  // bank, address, value
    for (int r = 0; r < rows; ++r) {
      const auto bank = static_cast<uint32_t>(rng() % 8);
      const uint32_t base =
          static_cast<uint32_t>(rng() % 4) * 512 + static_cast<uint32_t>(rng() % 64) * kCells;
      const bool full = rng() % 3 != 0;
      for (uint32_t c = 0; c < kCells; ++c) {
        if (full || rng() % 2 == 0)
          cells.push_back({bank, base + c, static_cast<uint32_t>(rng() & 0xFF)});
      }
    }
    std::shuffle(cells.begin(), cells.end(), rng);
    if (rng() % 5 == 0) add(hold_item(video::frame_tag(n - 1)));  // the frame before
    for (const auto& [bank, addr, value] : cells) {
      add(put_item(bank, addr, static_cast<uint8_t>(value), tag));
      if (rng() % 3 == 0) cycles(uniform(rng, 1, 4), rate, rng);
      if (rng() % 40 == 0)
        read(static_cast<unsigned>(rng() % 8), static_cast<uint32_t>(rng() % 2048));
      if (rng() % 40 == 0) read(bank, addr);  // a row being collected: its cells come back
    }
    add(flush_item(tag));
    cycles(uniform(rng, 0, 3) == 0 ? uniform(rng, 100, 400) : uniform(rng, 0, 40), rate, rng);
    add(hold_item(kHoldNone));
  }

 private:
  std::vector<Txn>& items_;
  Rows rows_;
};

constexpr const char* kWrite = "write access";
constexpr const char* kRead = "read access";
constexpr const char* kWriteFault = "write with a page fault";
constexpr const char* kWriteHit = "write to the open page";
constexpr const char* kReadFault = "read with a page fault";
constexpr const char* kForcedWrite = "write forced (waited L, the sampler loses)";
constexpr const char* kForcedRead = "read forced (the sampler loses)";
constexpr const char* kGranted = "sampler granted";
constexpr const char* kLostSecond = "sampler loses a fault's second cycle";
constexpr const char* kPartial = "partial row written (flushed)";
constexpr const char* kFull = "full row written";
constexpr const char* kHeld = "a ready row held by the swap barrier";
constexpr const char* kLost = "cell write lost (no free buffer)";
constexpr const char* kWaitZeroL = "write at L = 0";
constexpr const char* kReadBuffered = "read takes a cell from a row buffer";
constexpr const char* kDrained = "drained: the held frame's buffers all written";

}  // namespace

struct VideoRowsBlock::CoverState {
  Rows rows;
  size_t next = 0;
  bool pending_second = false;  // a faulting access started last cycle
  bool drained = true;          // the last cycle's drained
};

VideoRowsBlock::VideoRowsBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options) {
  add_level("hls", hls_level<desc::video_rows_sc, hls::VideoRowsSc>());
  TMU_ADD_RTL_LEVELS(video_rows, variant());
}

std::vector<Txn> VideoRowsBlock::setup_items() const { return {cfg_item(4, 0)}; }

std::vector<Txn> VideoRowsBlock::directed_items() const {
  std::vector<Txn> items;
  Stimulus s(items);
  std::mt19937_64 rng(options_.seed ^ 0x7177'0000'0000'0001ull);
  const auto row = [&](unsigned bank, uint32_t base, uint64_t tag, uint32_t cells = kCells) {
    for (uint32_t c = 0; c < cells; ++c) {
      s.add(put_item(bank, base + c, static_cast<uint8_t>(base + 17 * c + tag), tag));
    }
  };
  s.add(cfg_item(4, 0));
  // A full row, the sampler idle: written at once (a fault: no page open), then a second row
  // of the same page: no fault.
  row(0, 0, 1);
  s.cycles(3, 0.0, rng);
  row(0, 8, 1);
  s.cycles(3, 0.0, rng);
  // The sampler at every cycle: a row waits exactly L = 4 and takes the cycle (a fault: the
  // sampler moved the pages), then a partial row flushed.
  row(1, 512, 2);
  s.cycles(8, 1.0, rng);
  row(2, 1024, 2, 3);
  s.add(flush_item(2));
  s.cycles(8, 1.0, rng);
  // A read under a full sampler goes at once (read_wait 0); with read_wait 3 after 3 cycles.
  s.read(3, 40);
  s.cycles(3, 1.0, rng);
  s.add(cfg_item(4, 3));
  s.read(3, 48);
  s.cycles(6, 1.0, rng);
  // The swap barrier: frame 4's rows wait while hold_after(3), frame 3's go.
  s.add(hold_item(3));
  row(4, 64, 4);
  row(5, 64, 3);
  s.cycles(6, 0.0, rng);
  s.add(hold_item(kHoldNone));
  s.cycles(6, 0.0, rng);
  // L = 0: a ready row goes in the next cycle whatever the sampler does.
  s.add(cfg_item(0, 0));
  row(6, 2000, 5);
  s.cycles(4, 1.0, rng);
  // Nine rows in one bank, none complete: the ninth row's cells are lost; the flush writes eight.
  for (uint32_t r = 0; r < 9; ++r) row(7, 8 * r, 6, 2);
  s.add(flush_item(6));
  s.cycles(24, 0.5, rng);
  // Tags wrap: frame 1 after frame 0xFFFE is the newer one (VideoRowsTest.FrameTagsWrap...). A
  // read of a row both frames' buffers hold takes frame 1's cell; the barrier on frame 0xFFFE
  // holds frame 1's row while frame 0xFFFE's goes.
  s.add(cfg_item(4, 0));
  s.add(put_item(1, 4000, 10, 0xFFFE));
  s.add(put_item(1, 4000, 20, 1));
  s.read(1, 4000);
  s.cycles(2, 0.0, rng);
  s.add(hold_item(0xFFFE));
  s.add(flush_item(1));
  s.add(flush_item(0xFFFE));
  s.cycles(4, 0.0, rng);
  s.add(hold_item(kHoldNone));
  s.cycles(4, 0.0, rng);
  s.add(cfg_item(4, 0));
  return items;
}

std::vector<Txn> VideoRowsBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  Stimulus s(items);
  // Half the runs go through the tags' wrap (frame 0xFFFE, then tag 1), some 15 frames in.
  uint64_t n = rng() % 2 == 0 ? 1 : 0xFFF0;
  while (items.size() < count) {
    if (rng() % 4 == 0) {
      const uint32_t l = std::array<uint32_t, 6>{0, 1, 3, 8, 16, 64}[rng() % 6];
      s.add(cfg_item(l, std::array<uint32_t, 3>{0, 1, 5}[rng() % 3]));
    }
    s.frame(n++, rng);
  }
  return items;
}

std::unique_ptr<Model> VideoRowsBlock::golden() const { return std::make_unique<Golden>(); }

std::vector<std::string> VideoRowsBlock::coverage_cases() const {
  return {kWrite,      kRead,      kWriteFault,   kWriteHit, kReadFault, kForcedWrite,
          kForcedRead, kGranted,   kLostSecond,   kPartial,  kFull,      kHeld,
          kLost,       kWaitZeroL, kReadBuffered, kDrained};
}

void VideoRowsBlock::cover(const std::vector<Txn>& items, size_t index, const Txn& output,
                           Coverage& cov) const {
  // The harness calls this for the cycle items, in order; any other order replays.
  if (!cover_ || index < cover_->next) cover_ = std::make_shared<CoverState>();
  CoverState& c = *cover_;
  for (; c.next < index; ++c.next) {
    const Txn& t = items[c.next];
    if (D::table().is_cfg(t)) {
      c.rows.configure(t);
      continue;
    }
    const uint64_t lost = c.rows.rows().stats().lost_writes;
    Txn out;
    c.rows.step(t, &out);
    if (c.rows.rows().stats().lost_writes > lost) ++cov[kLost];
    if (static_cast<int>(t.f[0]) == D::op_cycle) {
      c.pending_second = out.f[D::out_fault] != 0;
      c.drained = out.f[D::out_drained] != 0;
    }
  }
  const bool sampler = items[index].f[D::cycle_sampler] != 0;
  const bool second = c.pending_second;  // this cycle is a fault's second
  Txn out;
  c.rows.step(items[index], &out);
  ++c.next;
  if (output.f[D::out_granted] != 0) ++cov[kGranted];
  if (sampler && second) ++cov[kLostSecond];
  c.pending_second = output.f[D::out_fault] != 0;
  if (output.f[D::out_write] != 0) {
    ++cov[kWrite];
    ++cov[output.f[D::out_fault] != 0 ? kWriteFault : kWriteHit];
    if (sampler) ++cov[kForcedWrite];
    bool full = true;
    for (uint32_t i = 0; i < kCells; ++i) full = full && output.f[D::out_mask + i] != 0;
    ++cov[full ? kFull : kPartial];
    if (c.rows.rows().config().max_wait == 0) ++cov[kWaitZeroL];
  }
  const bool was_drained = c.drained;
  c.drained = output.f[D::out_drained] != 0;
  if (c.drained && !was_drained) ++cov[kDrained];
  if (output.f[D::out_read] != 0) {
    ++cov[kRead];
    for (uint32_t i = 0; i < kCells; ++i) {
      if (output.f[D::out_mask + i] != 0) {
        ++cov[kReadBuffered];
        break;
      }
    }
    if (output.f[D::out_fault] != 0) ++cov[kReadFault];
    if (sampler) ++cov[kForcedRead];
  }
  if (output.f[D::out_write] == 0 && output.f[D::out_read] == 0 && !sampler &&
      !c.rows.rows().idle() && c.rows.rows().reads_pending() == 0 && !second) {
    ++cov[kHeld];  // the sampler left the cycle and a ready row did not take it
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(video_rows, VideoRowsBlock)
