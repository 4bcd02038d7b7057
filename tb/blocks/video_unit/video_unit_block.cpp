#include "blocks/video_unit/video_unit_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "blocks/video_rows/video_rows_block.hpp"
#include "blocks/video_unit/video_memory.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/video_unit_sc.hpp"
#include "rtl_models_video_unit.hpp"
#include "texram/layout.hpp"
#include "texram/video/video_unit.hpp"

TMU_DESCRIBE_SC(video_unit)

namespace tmu::tb {
namespace fmts = tmu::formats;
namespace video = texram::video;
using D = desc::video_unit;

video::VideoMapConfig video_unit_config(const Txn& cfg, uint32_t cells) {
  video::VideoMapConfig c;
  c.format.log2_w = static_cast<int>(cfg.f[D::cfg_log2_w]);
  c.format.log2_h = static_cast<int>(cfg.f[D::cfg_log2_h]);
  c.format.interlaced = cfg.f[D::cfg_interlaced] != 0;
  c.format.planes = cfg.f[D::cfg_four_planes] != 0 ? fmts::kPlanes : 1;
  c.base = static_cast<uint32_t>(cfg.f[D::cfg_base0]);
  c.base1 = static_cast<uint32_t>(cfg.f[D::cfg_base1]);
  // The unit's rows are the video_rows block's (tmu_video_rows at its defaults).
  c.arbiter = video_rows_config(static_cast<uint32_t>(cfg.f[D::cfg_max_wait]),
                                static_cast<uint32_t>(cfg.f[D::cfg_read_wait]));
  c.arbiter.segment_cells = cells;
  return c;
}

namespace {

constexpr uint64_t kWaitMax = 0xFFFF;  // the RTL's waits saturate at 16 bits

video::VideoItem item_of(const Txn& t) {
  return video::video_item(static_cast<uint8_t>(t.f[D::in_flags]),
                           static_cast<uint32_t>(t.f[D::in_texel]));
}

Txn in_item(const video::VideoItem& it) {
  return channel_item(D::table(), "in", {it.flags, video::texel_word(it)});
}

Txn cycle_item(bool sampler) { return channel_item(D::table(), "cycle", {sampler ? 1u : 0u}); }

// The golden unit over a run, stepped by items: what every model of the block (and the
// stimulus, which keeps the read queue within the unit's, and the coverage) steps.
class Unit {
 public:
  explicit Unit(uint32_t cells) : cells_(cells) {}

  void configure(const Txn& cfg) {
    const video::VideoMapConfig c = video_unit_config(cfg, cells_);
    if (c.format.log2_w > kVideoUnitMaxLog2 || c.format.log2_h > kVideoUnitMaxLog2) {
      throw std::runtime_error(fmt::format("video_unit: a {} x {} format, beyond the unit's {}",
                                           c.format.width(), c.format.height(),
                                           1u << kVideoUnitMaxLog2));
    }
    try {
      unit_.configure(c);
    } catch (const std::exception& e) {  // a refused map, or one written in the middle of a frame
      throw std::runtime_error(fmt::format("video_unit: {}", e.what()));
    }
  }

  // One stimulus item; a cycle item's output in *out and its access's memory requests, a row's
  // words in order (rows of 8 cells: one), in *reqs, if reqs is given.
  void step(const Txn& item, Txn* out, std::vector<Txn>* reqs = nullptr) {
    if (!unit_.configured()) {
      throw std::runtime_error("video_unit: an item before the first configuration");
    }
    if (static_cast<int>(item.f[0]) == D::op_in) {
      unit_.receive(item_of(item));
      if (map().row_buffers().reads_pending() > kVideoUnitReadQueue) {
        throw std::runtime_error(fmt::format(
            "video_unit: {} reads of the line above pending, more than the unit's queue of {}",
            map().row_buffers().reads_pending(), kVideoUnitReadQueue));
      }
      return;
    }
    const bool granted = unit_.cycle(item.f[D::cycle_sampler] != 0);
    using Kind = video::RowBuffers::Access::Kind;
    const video::RowBuffers::Access& a = map().row_buffers().last_access();
    *out = Txn{};
    out->f[D::out_granted] = granted;
    out->f[D::out_swap] = map().swapped();
    out->f[D::out_front] = static_cast<uint64_t>(map().front_buffer());
    if (a.kind == Kind::kNone) return;
    out->f[D::out_write] = a.kind == Kind::kWrite;
    out->f[D::out_read] = a.kind == Kind::kRead;
    out->f[D::out_fault] = a.fault;
    out->f[D::out_wait] = std::min(a.wait, kWaitMax);
    if (reqs == nullptr) return;
    reqs->clear();
    for (uint32_t w = 0; w < cells_; w += kVideoUnitWordCells) {
      Txn& req = reqs->emplace_back();
      req.f[D::mem_req_write] = a.kind == Kind::kWrite;
      req.f[D::mem_req_bank] = a.bank;
      req.f[D::mem_req_addr] = a.segment * cells_ + w;
      if (a.kind == Kind::kWrite) {
        for (uint32_t i = 0; i < kVideoUnitWordCells; ++i) {
          req.f[D::mem_req_mask + i] = a.mask[w + i];
          req.f[D::mem_req_data + i] = a.data[w + i];
        }
      }
    }
  }

  const video::VideoMap& map() const { return unit_.map(); }
  video::VideoUnit::Counts counts() const { return unit_.counts(); }
  Counters counters() const {
    const auto c32 = [](uint64_t v) { return v & 0xFFFF'FFFFu; };  // the RTL's 32-bit registers
    const video::VideoUnit::Counts c = unit_.counts();
    return {{"frames_shown", c32(c.shown)},      {"frames_dropped", c32(c.dropped)},
            {"overruns", c32(c.overruns)},       {"late_reads", c32(c.late_reads)},
            {"lost_writes", c32(c.lost_writes)}, {"forced", c32(c.forced)}};
  }

  uint32_t cells() const { return cells_; }

 private:
  uint32_t cells_;
  video::VideoUnit unit_;
};

class Golden : public Model {
 public:
  explicit Golden(uint32_t cells) : unit_(cells) {}
  void configure(const Txn& cfg) override { unit_.configure(cfg); }
  void step(const Txn& item, Sink& sink) override {
    Txn out;
    reqs_.clear();
    unit_.step(item, &out, &reqs_);
    if (static_cast<int>(item.f[0]) != D::op_cycle) return;
    for (const Txn& req : reqs_) sink.request(0, req);
    sink.output(out);
  }
  Counters counters() const override { return unit_.counters(); }

 private:
  Unit unit_;
  std::vector<Txn> reqs_;
};

int uniform(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

Txn cfg_item(const video::VideoFormat& f, uint32_t base0, uint32_t base1, uint32_t max_wait,
             uint32_t read_wait) {
  return channel_item(
      D::table(), "cfg",
      {static_cast<uint64_t>(f.log2_w), static_cast<uint64_t>(f.log2_h), f.interlaced ? 1u : 0u,
       f.planes == fmts::kPlanes ? 1u : 0u, base0, base1, max_wait, read_wait});
}

// Buffer 1 where the golden model puts it by default: the next page after buffer 0.
uint32_t default_base1(const video::VideoFormat& f, uint32_t base0) {
  return base0 + video::VideoMap::buffer_stride(texram::Geometry(f.log2_w, f.log2_h, f.planes));
}

// What a frame of the stimulus is.
struct FrameShape {
  int cycles_per_item = 1;  // memory cycles after each item (0: one cycle every 4 items)
  double sampler = 0.0;     // the share of cycles the sampler wants
  enum class Defect { kNone, kMissing, kCut } defect = Defect::kNone;
};

// A run of video maps and frames, kept within the unit's read queue by a mirror of the golden
// unit.
class Stimulus {
 public:
  Stimulus(std::vector<Txn>& items, std::mt19937_64& rng, uint32_t cells)
      : items_(items), rng_(rng), unit_(cells) {}
  void add(const Txn& t) {
    if (D::table().is_cfg(t)) {
      unit_.configure(t);
      format_ = unit_.map().config().format;
    } else {
      Txn out;
      unit_.step(t, &out);
    }
    items_.push_back(t);
  }
  void configure(const video::VideoFormat& f, uint32_t base0, uint32_t base1, uint32_t max_wait,
                 uint32_t read_wait) {
    add(cfg_item(f, base0, base1, max_wait, read_wait));
  }
  void cycles(int n, double sampler) {
    for (int i = 0; i < n; ++i) {
      add(cycle_item(static_cast<double>(rng_() % 1000) < sampler * 1000.0));
    }
  }
  // Frame k of test_frame's video in the format, shaped.
  void frame(uint32_t k, const FrameShape& shape) {
    std::vector<video::VideoItem> v = video::frame_items(format_, video::test_frame(format_, k));
    if (shape.defect == FrameShape::Defect::kMissing && v.size() > 2) {
      v.erase(v.begin() + 1 + static_cast<ptrdiff_t>(rng_() % (v.size() - 2)));
    } else if (shape.defect == FrameShape::Defect::kCut && v.size() > 1) {
      v.resize(1 + rng_() % (v.size() - 1));
    }
    port_items(v, shape);
  }
  // Port items with memory cycles after each, as the shape says.
  void port_items(const std::vector<video::VideoItem>& v, const FrameShape& shape) {
    for (size_t i = 0; i < v.size(); ++i) {
      // The source does not wait, but the stimulus keeps the read queue within the unit's.
      while (unit_.map().row_buffers().reads_pending() > kVideoUnitReadQueue / 2) {
        cycles(1, shape.sampler);
      }
      add(in_item(v[i]));
      cycles(shape.cycles_per_item > 0 ? shape.cycles_per_item : (i % 4 == 3 ? 1 : 0),
             shape.sampler);
    }
  }
  // Cycles without the sampler until every row is written and the last swap is done (every row
  // is written at once and the swap follows: it ends).
  void drain() {
    while (unit_.map().swap_pending() || !unit_.map().row_buffers().idle()) cycles(1, 0.0);
    cycles(2, 0.0);
  }
  const Unit& unit() const { return unit_; }

 private:
  std::vector<Txn>& items_;
  std::mt19937_64& rng_;
  Unit unit_;
  video::VideoFormat format_;
};

// A format the unit takes whose interlaced lines' reads fit its queue: at most 64 bytes a line.
video::VideoFormat draw_format(std::mt19937_64& rng) {
  video::VideoFormat f;
  f.planes = rng() % 3 == 0 ? fmts::kPlanes : 1;
  f.interlaced = rng() % 2 == 0;
  const int top = rng() % 6 == 0 ? 6 : 4;
  f.log2_h = uniform(rng, 0, top);
  f.log2_w = uniform(rng, 0, f.interlaced && f.planes == fmts::kPlanes ? std::min(top, 4) : top);
  return f;
}

FrameShape draw_shape(std::mt19937_64& rng) {
  FrameShape s;
  s.cycles_per_item = std::array<int, 5>{0, 1, 1, 2, 4}[rng() % 5];
  s.sampler = std::array<double, 5>{0.0, 0.3, 0.7, 0.95, 1.0}[rng() % 5];
  const uint64_t d = rng() % 10;
  s.defect = d == 0 ? FrameShape::Defect::kMissing
                    : (d == 1 ? FrameShape::Defect::kCut : FrameShape::Defect::kNone);
  return s;
}

constexpr const char* kWrite = "write access";
constexpr const char* kWriteFault = "write with a page fault";
constexpr const char* kRead = "read of the line above";
constexpr const char* kReadBuffered = "read takes a cell from a row buffer";
constexpr const char* kForced = "access forced (the sampler loses)";
constexpr const char* kGranted = "sampler granted";
constexpr const char* kLostCycle = "sampler cycle lost (wanted, not granted)";
constexpr const char* kSwap0 = "swap to buffer 0";
constexpr const char* kSwap1 = "swap to buffer 1";
constexpr const char* kDropped = "frame dropped (malformed)";
constexpr const char* kOverrun = "overrun (a frame complete before the previous swap)";
constexpr const char* kLate = "late read (a line before its line above)";
constexpr const char* kLost = "cell write lost (no free buffer)";
constexpr const char* kTwoLine = "two-line interlaced frame (line 0 as it arrives)";
constexpr const char* kFourPlanes = "four-plane video";
constexpr const char* kInterlaced = "interlaced field-2 line";
constexpr const char* kNewMap = "a new video map (reconfiguration)";

}  // namespace

Txn video_unit_config_item(const video::VideoMapConfig& c) {
  const uint32_t base1 = c.base1 ? *c.base1 : default_base1(c.format, c.base);
  return cfg_item(c.format, c.base, base1, c.arbiter.max_wait, c.arbiter.read_wait);
}

VideoUnitFeedItems video_unit_feed_items(const video::VideoMapConfig& config,
                                         const std::vector<std::vector<video::VideoItem>>& frames) {
  const uint32_t cells = config.arbiter.segment_cells;
  if (cells != kVideoUnitCells && cells != kVideoUnitPageCells) {
    throw std::invalid_argument(fmt::format("video_unit: rows of {} cells", cells));
  }
  for (int rate = 1; rate <= 16; rate *= 2) {
    VideoUnitFeedItems feed;
    feed.cycles_per_item = rate;
    std::mt19937_64 rng(1);  // unused: the sampler wants no cycle
    Stimulus s(feed.items, rng, cells);
    s.add(video_unit_config_item(config));
    bool whole = true;
    for (size_t k = 0; k < frames.size() && whole; ++k) {
      const video::VideoUnit::Counts before = s.unit().counts();
      s.port_items(frames[k], {rate, 0.0, FrameShape::Defect::kNone});
      s.drain();
      const video::VideoUnit::Counts after = s.unit().counts();
      whole = after.shown == before.shown + 1 && after.lost_writes == before.lost_writes;
    }
    if (whole) return feed;
  }
  throw std::runtime_error(
      "video_unit: cell writes lost even at one texel in 16 cycles (more rows a bank than the "
      "unit's 8 row buffers)");
}

struct VideoUnitBlock::CoverState {
  explicit CoverState(uint32_t cells) : unit(cells) {}
  Unit unit;
  size_t next = 0;
  size_t maps = 0;
};

VideoUnitBlock::VideoUnitBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options) {
  if (options_.video_cells != kVideoUnitCells && options_.video_cells != kVideoUnitPageCells) {
    throw std::invalid_argument(fmt::format("video_unit: rows of {} cells; the unit has {} or {}",
                                            options_.video_cells, kVideoUnitCells,
                                            kVideoUnitPageCells));
  }
  add_level("hls", hls_level<desc::video_unit_sc, hls::VideoUnitSc>(options_.video_cells));
  TMU_ADD_RTL_LEVELS(video_unit, variant());
}

std::string VideoUnitBlock::variant() const {
  return options_.video_cells == kVideoUnitPageCells ? "page" : "";
}

std::vector<Txn> VideoUnitBlock::setup_items() const {
  const video::VideoFormat f{2, 2, false, 1};
  return {cfg_item(f, 0, default_base1(f, 0), 4, 0)};
}

std::unique_ptr<Environment> VideoUnitBlock::environment(uint64_t seed) const {
  return std::make_unique<VideoMemory>(1, 2, seed);
}

std::vector<Txn> VideoUnitBlock::directed_items() const {
  std::vector<Txn> items;
  std::mt19937_64 rng(options_.seed ^ 0x71DE'0000'0000'0003ull);
  Stimulus s(items, rng, options_.video_cells);
  const auto map = [&](video::VideoFormat f, uint32_t base0, uint32_t max_wait,
                       uint32_t read_wait) {
    s.configure(f, base0, default_base1(f, base0), max_wait, read_wait);
  };
  // 4 x 4 progressive, the sampler idle: each frame written at once and swapped in; buffers 1,
  // 0, 1.
  map({2, 2, false, 1}, 0, 4, 0);
  for (uint32_t k = 0; k < 3; ++k) s.frame(k, {1, 0.0, FrameShape::Defect::kNone});
  s.drain();
  // 8 x 8 interlaced four planes under a full sampler: the line above read a line ahead, every
  // access forced after L = 4 (reads at once).
  map({3, 3, true, 4}, 100, 4, 0);
  for (uint32_t k = 0; k < 2; ++k) s.frame(k, {2, 1.0, FrameShape::Defect::kNone});
  s.drain();
  // A two-line interlaced frame: line 0 taken into the shift registers as it arrives.
  map({2, 1, true, 4}, 7, 8, 0);
  for (uint32_t k = 0; k < 2; ++k) s.frame(k, {1, 0.5, FrameShape::Defect::kNone});
  s.drain();
  // A frame with a texel missing is dropped; the next goes to the same buffer.
  map({2, 2, true, 1}, 0, 4, 0);
  s.frame(0, {1, 0.0, FrameShape::Defect::kNone});
  s.frame(1, {1, 0.0, FrameShape::Defect::kMissing});
  s.frame(2, {1, 0.0, FrameShape::Defect::kNone});
  s.drain();
  // 1 x 1 frames, one texel a cycle, the sampler at every cycle: each frame completes long
  // before the previous one's swap (L = 16): overruns.
  map({0, 0, false, 1}, 3, 16, 0);
  for (uint32_t k = 0; k < 6; ++k) s.frame(k, {1, 1.0, FrameShape::Defect::kNone});
  s.drain();
  // Interlaced, four items a cycle, reads bounded by 40 cycles under a full sampler: field 2's
  // first line begins before its line above is read (late reads).
  map({3, 2, true, 1}, 0, 4, 40);
  for (uint32_t k = 0; k < 2; ++k) s.frame(k, {0, 1.0, FrameShape::Defect::kNone});
  s.drain();
  // 16 x 16 four planes, four items a cycle under a full sampler at L = 64: more rows than a
  // bank's 8 buffers wait (cell writes lost).
  map({4, 4, false, 4}, 0, 64, 0);
  s.frame(0, {0, 1.0, FrameShape::Defect::kNone});
  s.drain();
  if (options_.video_cells > 32) {
    // Rows of a page hold that frame in a few rows a bank: 128 x 64 four planes at the longest
    // bound L = 0xFFFF fill more than 8 rows a bank before any may be written.
    map({7, 6, false, 4}, 0, 0xFFFF, 0);
    s.frame(0, {0, 1.0, FrameShape::Defect::kNone});
    s.drain();
  }
  items.push_back(setup_items().front());  // the random items go on in the setup's map
  return items;
}

// The figure's workload (BlockOptions::video_workload) as video::run feeds it in
// VideoFigureTest: two frames of a 512 x 512 video at 30 frames per second on video::at_rate's
// schedule, the sampler wanting every cycle, L = 64, then cycles until the last frame is
// swapped in and every row is written.
std::vector<Txn> VideoUnitBlock::workload_items() const {
  const std::string& w = options_.video_workload;
  const video::VideoFormat f{9, 9, w[1] == 'i', w[0] == '4' ? fmts::kPlanes : 1};
  std::vector<Txn> items;
  std::mt19937_64 rng(1);  // unused: the sampler wants every cycle
  Stimulus s(items, rng, options_.video_cells);
  s.configure(f, 0, default_base1(f, 0), 64, 0);
  std::vector<video::VideoItem> stream;
  for (uint32_t k = 0; k < 2; ++k) {
    const std::vector<video::VideoItem> v = video::frame_items(f, video::test_frame(f, k));
    stream.insert(stream.end(), v.begin(), v.end());
  }
  video::at_rate(
      stream.size(), video::video_rate(512, 512, 30), [&](size_t i) { s.add(in_item(stream[i])); },
      [&] { s.add(cycle_item(true)); });
  while (s.unit().map().swap_pending() || !s.unit().map().row_buffers().idle()) {
    s.add(cycle_item(true));
  }
  return items;
}

std::string VideoUnitBlock::repro_options() const {
  std::string out = DescribedBlock::repro_options();
  if (!options_.video_workload.empty()) {
    out += (out.empty() ? "" : " ") + std::string("--video-workload ") + options_.video_workload;
  }
  return out;
}

std::vector<Txn> VideoUnitBlock::random_items(std::mt19937_64& rng, size_t count) const {
  if (!options_.video_workload.empty()) return workload_items();
  std::vector<Txn> items;
  Stimulus s(items, rng, options_.video_cells);
  s.add(setup_items().front());
  uint32_t k = 0;
  while (items.size() < count) {
    if (rng() % 3 == 0) {
      const video::VideoFormat f = draw_format(rng);
      const auto low = static_cast<uint32_t>(rng() % 2048);
      const uint32_t next = low + texram::Geometry(f.log2_w, f.log2_h, f.planes).bank_cells() +
                            static_cast<uint32_t>(rng() % 16);
      // Buffer 1 on the page after buffer 0 (the default), right behind it, or before it.
      const uint64_t pick = rng() % 3;
      s.configure(f, pick == 2 ? next : low,
                  pick == 0 ? default_base1(f, low) : (pick == 1 ? next : low),
                  std::array<uint32_t, 6>{0, 1, 4, 8, 16, 64}[rng() % 6],
                  std::array<uint32_t, 3>{0, 1, 5}[rng() % 3]);
    }
    const int frames = uniform(rng, 1, 4);
    for (int i = 0; i < frames; ++i) {
      FrameShape shape = draw_shape(rng);
      if (i + 1 == frames) shape.defect = FrameShape::Defect::kNone;  // whole before a new map
      s.frame(k++, shape);
    }
    s.drain();
  }
  return items;
}

std::unique_ptr<Model> VideoUnitBlock::golden() const {
  return std::make_unique<Golden>(options_.video_cells);
}

std::vector<std::string> VideoUnitBlock::coverage_cases() const {
  return {kWrite,     kWriteFault, kRead,       kReadBuffered, kForced,  kGranted,
          kLostCycle, kSwap0,      kSwap1,      kDropped,      kOverrun, kLate,
          kLost,      kTwoLine,    kFourPlanes, kInterlaced,   kNewMap};
}

void VideoUnitBlock::cover(const std::vector<Txn>& items, size_t index, const Txn& output,
                           Coverage& cov) const {
  // The harness calls this for the cycle items, in order; any other order replays.
  if (!cover_ || index < cover_->next) cover_ = std::make_shared<CoverState>(options_.video_cells);
  CoverState& c = *cover_;
  for (; c.next < index; ++c.next) {
    const Txn& t = items[c.next];
    if (D::table().is_cfg(t)) {
      const video::VideoMap* before = c.maps > 0 ? &c.unit.map() : nullptr;
      c.unit.configure(t);
      if (before != nullptr && &c.unit.map() != before) ++cov[kNewMap];
      ++c.maps;
      continue;
    }
    const video::VideoUnit::Counts before = c.unit.counts();
    Txn out;
    c.unit.step(t, &out);
    const video::VideoUnit::Counts after = c.unit.counts();
    if (after.dropped > before.dropped) ++cov[kDropped];
    if (after.overruns > before.overruns) ++cov[kOverrun];
    if (after.late_reads > before.late_reads) ++cov[kLate];
    if (after.lost_writes > before.lost_writes) ++cov[kLost];
    const video::VideoMap& m = c.unit.map();
    const video::VideoFormat& f = m.config().format;
    if (static_cast<int>(t.f[0]) == D::op_in && f.fields() && (item_of(t).flags & 8u) != 0) {
      ++cov[kInterlaced];
      if (f.height() == 2) ++cov[kTwoLine];
    }
  }
  Txn out;
  c.unit.step(items[index], &out);
  ++c.next;
  const video::VideoMap& m = c.unit.map();
  if (m.config().format.planes == fmts::kPlanes) ++cov[kFourPlanes];
  if (output.f[D::out_granted] != 0) ++cov[kGranted];
  if (items[index].f[D::cycle_sampler] != 0 && output.f[D::out_granted] == 0) ++cov[kLostCycle];
  const bool access = output.f[D::out_write] != 0 || output.f[D::out_read] != 0;
  if (access && items[index].f[D::cycle_sampler] != 0) ++cov[kForced];
  if (output.f[D::out_write] != 0) {
    ++cov[kWrite];
    if (output.f[D::out_fault] != 0) ++cov[kWriteFault];
  }
  if (output.f[D::out_read] != 0) {
    ++cov[kRead];
    const auto& mask = m.row_buffers().last_access().mask;
    if (std::find(mask.begin(), mask.end(), true) != mask.end()) ++cov[kReadBuffered];
  }
  if (output.f[D::out_swap] != 0) ++cov[output.f[D::out_front] != 0 ? kSwap1 : kSwap0];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(video_unit, VideoUnitBlock)
