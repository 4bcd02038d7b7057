#include "texram/video/video_map.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

#include "texram/chip/chip_memory.hpp"

namespace tmu::texram::video {
namespace {

const VideoMapConfig& checked(const VideoMapConfig& c) {
  if (c.drf < 1 || c.drf > chip::kDrfs) {
    throw std::invalid_argument("VideoMap: DRF " + std::to_string(c.drf) + " outside 1.." +
                                std::to_string(chip::kDrfs));
  }
  return c;
}

BankImage make_memory(const VideoMapConfig& c, const Geometry& g) {
  const uint64_t base1 = c.base1 ? *c.base1 : uint64_t{c.base} + VideoMap::buffer_stride(g);
  const uint64_t end = std::max<uint64_t>(c.base, base1) + g.bank_cells();
  if (end > chip::kBankCells) {
    throw std::invalid_argument("VideoMap: two buffers of " + std::to_string(g.bank_cells()) +
                                " cells a bank at " + std::to_string(c.base) + " and " +
                                std::to_string(base1) + " end beyond the bank's " +
                                std::to_string(chip::kBankCells));
  }
  if (std::max<uint64_t>(c.base, base1) - std::min<uint64_t>(c.base, base1) < g.bank_cells()) {
    throw std::invalid_argument("VideoMap: buffers of " + std::to_string(g.bank_cells()) +
                                " cells a bank at " + std::to_string(c.base) + " and " +
                                std::to_string(base1) + " overlap");
  }
  BankImage m;
  for (auto& bank : m) bank.assign(page_up(static_cast<uint32_t>(end)), 0);  // whole segments
  return m;
}

}  // namespace

VideoMap::VideoMap(const VideoMapConfig& config)
    : config_(checked(config)),
      geometry_(config.format.log2_w, config.format.log2_h, config.format.planes),
      memory_(make_memory(config, geometry_)),
      rows_(config.arbiter, memory_),
      receiver_(config.format) {
  chip::Drf& d = drfs_[static_cast<size_t>(config.drf - 1)];
  d.base = buffer_base(0);
  d.log2_w = config.format.log2_w;
  d.log2_h = config.format.log2_h;
  d.sampler.kind = config.format.planes == 1 ? TexelKind::kLuminance : TexelKind::kTrueColour;
  for (auto& slot : above_) slot.assign(line_cells(), 0);
}

uint32_t VideoMap::line_cells() const {
  return static_cast<uint32_t>(config_.format.planes) * (geometry_.stored_width(0) / 2);
}

uint32_t VideoMap::line_start(uint32_t line) const { return (line >> 1) * line_cells(); }

uint8_t& VideoMap::above_cell(uint32_t line, uint32_t x, int p) {
  const size_t slot = 2 * ((line >> 1) & 1u) + (x & 1u);
  return above_[slot]
               [static_cast<size_t>(config_.format.planes) * (x >> 1) + static_cast<size_t>(p)];
}

void VideoMap::begin_frame() {
  FrameRecord f;
  f.tag = frames_.size() + 1;
  f.buffer = 1 - newest_;
  f.begin_cycle = cycles();
  frames_.push_back(f);
  reads_needed_.assign(config_.format.height(), 0);
  streams_.clear();
  const VideoFormat& v = config_.format;
  for (int p = 0; p < v.planes; ++p) {
    streams_.emplace_back(MipgenConfig{v.log2_w, v.log2_h, v.interlaced, v.planes, p});
  }
}

void VideoMap::end_frame(bool complete) {
  FrameRecord& f = frames_.back();
  f.end_cycle = cycles();
  rows_.flush(frame_tag(f.tag));
  if (!complete) {
    f.dropped = true;
    return;
  }
  if (pending_) {  // the memory cannot keep up: not shown, like a dropped frame
    f.dropped = true;
    ++overruns_;
    return;
  }
  f.complete = true;
  newest_ = f.buffer;
  pending_ = frames_.size() - 1;
  rows_.hold_after(frame_tag(f.tag));  // the next frame writes the front buffer: held until
                                       // the swap
}

void VideoMap::read_line_above(uint32_t above, uint32_t line) {
  const uint32_t base = buffer_base(frames_.back().buffer);
  std::vector<std::pair<unsigned, uint32_t>> segments;
  for (uint32_t x = 0; x < geometry_.stored_width(0); ++x) {
    for (int p = 0; p < config_.format.planes; ++p) {
      const BankCell c = geometry_.cell(0, x, above, p);
      const std::pair<unsigned, uint32_t> s{c.bank,
                                            (base + c.address) / config_.arbiter.segment_cells};
      if (std::find(segments.begin(), segments.end(), s) == segments.end()) segments.push_back(s);
    }
  }
  for (const auto& [bank, segment] : segments) {
    reads_needed_[line] = rows_.request_read(bank, segment);
    line_reads_.push_back({above, base});
  }
}

void VideoMap::capture(const std::vector<uint8_t>& memory_cells) {
  const RowBuffers::Access& a = rows_.last_access();
  const uint32_t n = config_.arbiter.segment_cells;
  if (a.kind != RowBuffers::Access::Kind::kRead || line_reads_.empty() ||
      memory_cells.size() != n) {
    throw std::logic_error("VideoMap::capture: no read to capture, or not a segment of cells");
  }
  const LineRead r = line_reads_.front();
  line_reads_.pop_front();
  const int planes = config_.format.planes;
  const uint32_t first = r.base + line_start(r.line);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t address = a.segment * n + i;
    if (address < first || address - first >= line_cells()) continue;  // another line's cell
    const uint32_t rel = address - first;
    const uint32_t x = 2 * (rel / static_cast<uint32_t>(planes)) + (a.bank & 1u);
    above_cell(r.line, x, static_cast<int>(rel % static_cast<uint32_t>(planes))) =
        a.mask[i] ? a.data[i] : memory_cells[i];
  }
}

void VideoMap::receive(const VideoItem& item) {
  const Received r = receiver_.step(item);
  if (r.dropped) end_frame(false);
  if (!r.accepted) return;
  if (r.frame_start) begin_frame();
  const FrameRecord& f = frames_.back();
  const uint32_t base = buffer_base(f.buffer);
  // Interlaced: the line above each field-2 line is read into the shift registers a line ahead:
  // line 0 at the start of field 1's last line, line y + 1 at the start of field-2 line y. (A
  // two-line frame's line 0 is the line just received: taken as it arrives, no read.)
  const uint32_t h = config_.format.height();
  if (config_.format.fields() && h > 2 && r.x == 0 && !config_.arbiter.direct) {
    if ((r.y & 1u) != 0 && rows_.reads_completed() < reads_needed_[r.y]) ++late_reads_;
    if (r.y == h - 2) read_line_above(0, 1);
    if ((r.y & 1u) != 0 && r.y + 2 < h) read_line_above(r.y + 1, r.y + 2);
  }
  for (int p = 0; p < config_.format.planes; ++p) {
    MipgenStream& s = streams_[static_cast<size_t>(p)];
    if (s.next_x() != r.x || s.next_y() != r.y) {
      throw std::logic_error("VideoMap: the receiver and the generator disagree on the position");
    }
    MipgenInput in{item.bytes[static_cast<size_t>(p)], 0};
    if (h == 2 && config_.format.fields() && r.y == 0) above_cell(0, r.x, p) = in.texel;
    if (s.needs_above()) {
      if (config_.arbiter.direct) {  // the reference: no reads, the memory as written
        const BankCell c = geometry_.cell(0, r.x, r.y - 1, p);
        in.above = memory_[c.bank][base + c.address];
      } else {
        in.above = above_cell(r.y - 1, r.x, p);
      }
    }
    writes_.clear();
    s.step(in, writes_);
    for (const CellWrite& w : writes_)
      rows_.put(w.cell.bank, base + w.cell.address, w.value, frame_tag(f.tag));
  }
  if (r.frame_end) end_frame(true);
}

bool VideoMap::cycle(bool sampler_wants) {
  const bool granted = rows_.cycle(sampler_wants);
  const RowBuffers::Access& a = rows_.last_access();
  if (a.kind == RowBuffers::Access::Kind::kRead && !config_.external_reads) {
    const uint32_t n = config_.arbiter.segment_cells;
    const auto& bank = memory_[a.bank];
    capture({bank.begin() + a.segment * n, bank.begin() + (a.segment + 1) * n});
  }
  swapped_ = false;
  if (pending_ && rows_.held_frame_written()) {
    FrameRecord& f = frames_[*pending_];
    chip::apply(drfs_, {static_cast<uint8_t>(config_.drf),
                        static_cast<uint8_t>(chip::DrfFieldId::kBase), buffer_base(f.buffer)});
    front_ = f.buffer;
    front_tag_ = f.tag;
    f.swap_cycle = cycles();
    swapped_ = true;
    pending_.reset();
    rows_.hold_after(kTagNone);
  }
  return granted;
}

uint8_t VideoMap::read(int buffer, int level, uint32_t x, uint32_t y, int plane) const {
  const BankCell c = geometry_.cell(level, x, y, plane);
  return memory_[c.bank][buffer_base(buffer) + c.address];
}

Pyramid8 VideoMap::read_pyramid(int buffer, int plane) const {
  Pyramid8 p;
  for (int l = 0; l < geometry_.levels(); ++l) {
    Level8 level(geometry_.texel_width(l), geometry_.texel_height(l));
    for (uint32_t y = 0; y < level.height; ++y) {
      for (uint32_t x = 0; x < level.width; ++x) level.at(x, y) = read(buffer, l, x, y, plane);
    }
    p.push_back(std::move(level));
  }
  return p;
}

void at_rate(size_t n, VideoRate rate, const std::function<void(size_t)>& arrive,
             const std::function<void()>& cycle) {
  uint64_t acc = 0;
  for (size_t i = 0; i < n;) {
    for (acc += rate.num; acc >= rate.den && i < n; acc -= rate.den) arrive(i++);
    cycle();
  }
}

uint64_t run(VideoMap& map, const std::vector<VideoItem>& items, const RunOptions& options) {
  std::mt19937_64 rng(options.seed);
  auto wants = [&] {
    switch (options.sampler) {
      case SamplerPattern::kNone:
        return false;
      case SamplerPattern::kFull:
        return true;
      case SamplerPattern::kRandom:
        return rng() % 100 < options.random_percent;
    }
    return false;
  };
  uint64_t n = 0;
  auto step = [&] {
    const bool granted = map.cycle(wants());
    if (options.on_cycle) options.on_cycle(map, granted);
    ++n;
  };
  at_rate(
      items.size(), options.rate, [&](size_t i) { map.receive(items[i]); }, step);
  if (options.drain_cycles > 0) {
    for (uint64_t k = 0; k < options.drain_cycles; ++k) step();
  } else {
    while (map.swap_pending() || !map.row_buffers().idle()) step();
  }
  return n;
}

}  // namespace tmu::texram::video
