#include "texram/video/row_buffers.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace tmu::texram::video {

RowBuffers::RowBuffers(const ArbiterConfig& config, BankImage& memory)
    : config_(config), memory_(memory) {
  const uint32_t page = kPageCells;
  if (!std::has_single_bit(config.segment_cells) || config.segment_cells > page) {
    throw std::invalid_argument("RowBuffers: a segment is a power of two up to " +
                                std::to_string(page) + " cells");
  }
  if (config.buffers_per_bank < 1) {
    throw std::invalid_argument("RowBuffers: at least one buffer per bank");
  }
  if (!config.direct) {
    buffers_.resize(8 * static_cast<size_t>(config.buffers_per_bank));
    for (size_t i = 0; i < buffers_.size(); ++i) {
      buffers_[i].bank = static_cast<unsigned>(i / static_cast<size_t>(config.buffers_per_bank));
      buffers_[i].data.assign(config.segment_cells, 0);
      buffers_[i].valid.assign(config.segment_cells, false);
    }
  }
}

RowBuffers::Buffer* RowBuffers::collecting(unsigned bank, uint32_t segment, uint32_t tag) {
  const size_t n = static_cast<size_t>(config_.buffers_per_bank);
  Buffer* free = nullptr;
  for (size_t i = bank * n; i < (bank + 1) * n; ++i) {
    Buffer& b = buffers_[i];
    if (b.state == State::kCollecting && b.segment == segment && b.tag == tag) return &b;
    if (b.state == State::kFree && free == nullptr) free = &b;
  }
  if (free != nullptr) {
    free->state = State::kCollecting;
    free->segment = segment;
    free->tag = tag;
    free->count = 0;
    std::fill(free->valid.begin(), free->valid.end(), false);
  }
  return free;
}

void RowBuffers::put(unsigned bank, uint32_t address, uint8_t value, uint32_t tag) {
  ++stats_.cells_in;
  if (config_.direct) {
    memory_.at(bank).at(address) = value;
    ++stats_.cells_written;
    return;
  }
  Buffer* b = collecting(bank, address / config_.segment_cells, tag);
  if (b == nullptr) {
    ++stats_.lost_writes;
    return;
  }
  const uint32_t i = address % config_.segment_cells;
  b->data[i] = value;
  if (!b->valid[i]) {
    b->valid[i] = true;
    ++b->count;
  }
  note_busy();
  if (b->count == config_.segment_cells) make_ready(static_cast<size_t>(b - buffers_.data()));
}

void RowBuffers::make_ready(size_t id) {
  buffers_[id].state = State::kReady;
  buffers_[id].ready_cycle = stats_.cycles;
  ready_.push_back(id);
  stats_.max_ready = std::max(stats_.max_ready, ready_.size());
}

void RowBuffers::flush(uint32_t tag) {
  for (size_t i = 0; i < buffers_.size(); ++i) {
    if (buffers_[i].state == State::kCollecting && buffers_[i].tag == tag) make_ready(i);
  }
}

const RowBuffers::Buffer* RowBuffers::newest_holding(unsigned bank, uint32_t segment,
                                                     uint32_t i) const {
  const Buffer* newest = nullptr;
  for (const Buffer& b : buffers_) {
    if (b.state != State::kFree && b.bank == bank && b.segment == segment && b.valid[i] &&
        (newest == nullptr || tag_not_before(b.tag, newest->tag))) {
      newest = &b;
    }
  }
  return newest;
}

size_t RowBuffers::buffers_of(uint32_t tag) const {
  return static_cast<size_t>(std::count_if(buffers_.begin(), buffers_.end(), [&](const Buffer& b) {
    return b.state != State::kFree && b.tag == tag;
  }));
}

size_t RowBuffers::buffers_busy() const {
  return static_cast<size_t>(std::count_if(
      buffers_.begin(), buffers_.end(), [](const Buffer& b) { return b.state != State::kFree; }));
}

void RowBuffers::note_busy() {
  const size_t n = static_cast<size_t>(config_.buffers_per_bank);
  size_t total = 0;
  for (size_t bank = 0; bank < 8; ++bank) {
    size_t busy = 0;
    for (size_t i = bank * n; i < (bank + 1) * n; ++i) busy += buffers_[i].state != State::kFree;
    stats_.max_busy_bank = std::max(stats_.max_busy_bank, busy);
    total += busy;
  }
  stats_.max_busy_total = std::max(stats_.max_busy_total, total);
}

void RowBuffers::write_access(size_t id) {
  Buffer& b = buffers_[id];
  const uint32_t first = b.segment * config_.segment_cells;
  const uint32_t page = first >> kPageBits;
  const bool fault = open_page_[b.bank] != page;
  open_page_[b.bank] = page;
  for (uint32_t i = 0; i < config_.segment_cells; ++i) {
    if (b.valid[i]) memory_.at(b.bank).at(first + i) = b.data[i];
  }
  const uint64_t latency = stats_.cycles - b.ready_cycle;
  last_.kind = Access::Kind::kWrite;
  last_.bank = b.bank;
  last_.segment = b.segment;
  last_.fault = fault;
  last_.mask = b.valid;
  last_.data.assign(config_.segment_cells, 0);
  for (uint32_t i = 0; i < config_.segment_cells; ++i) {
    if (b.valid[i]) last_.data[i] = b.data[i];
  }
  last_.wait = latency;
  stats_.max_latency = std::max(stats_.max_latency, latency);
  stats_.min_latency = std::min(stats_.min_latency, latency);
  stats_.latency_sum += latency;
  ++stats_.write_accesses;
  stats_.cells_written += b.count;
  stats_.write_cycles += fault ? 2 : 1;
  stats_.page_faults += fault;
  b.state = State::kWriting;
  writing_ = id;
  busy_ = fault ? 2 : 1;
}

uint64_t RowBuffers::request_read(unsigned bank, uint32_t segment) {
  reads_.push_back({bank, segment, stats_.cycles});
  return ++reads_requested_;
}

void RowBuffers::read_access() {
  const Read r = reads_.front();
  reads_.pop_front();
  const uint32_t page = (r.segment * config_.segment_cells) >> kPageBits;
  const bool fault = open_page_[r.bank] != page;
  open_page_[r.bank] = page;
  stats_.max_read_latency = std::max(stats_.max_read_latency, stats_.cycles - r.request_cycle);
  last_ = Access{};
  last_.kind = Access::Kind::kRead;
  last_.bank = r.bank;
  last_.segment = r.segment;
  last_.fault = fault;
  last_.wait = stats_.cycles - r.request_cycle;
  // The cells a row buffer still holds, which the read's data take instead of the memory's.
  last_.mask.assign(config_.segment_cells, false);
  last_.data.assign(config_.segment_cells, 0);
  for (uint32_t i = 0; i < config_.segment_cells; ++i) {
    if (const Buffer* b = newest_holding(r.bank, r.segment, i)) {
      last_.mask[i] = true;
      last_.data[i] = b->data[i];
    }
  }
  ++stats_.read_accesses;
  stats_.read_cycles += fault ? 2 : 1;
  stats_.read_faults += fault;
  ++reads_completed_;
  reading_ = true;
  busy_ = fault ? 2 : 1;
}

bool RowBuffers::cycle(bool sampler_wants) {
  stats_.sampler_wanted += sampler_wants;
  last_.kind = Access::Kind::kNone;
  bool granted = false;
  if (busy_ == 0 && !reads_.empty() &&
      (!sampler_wants || stats_.cycles - reads_.front().request_cycle >= config_.read_wait)) {
    stats_.forced_writes += sampler_wants;  // a read first: it has a deadline, its line
    read_access();
  } else if (busy_ == 0 && !ready_.empty()) {
    // The oldest ready buffer not held by the swap barrier.
    auto it = std::find_if(ready_.begin(), ready_.end(), [&](size_t id) {
      return hold_after_ == kTagNone || tag_not_before(hold_after_, buffers_[id].tag);
    });
    if (it != ready_.end()) {
      const size_t id = *it;
      const bool due = stats_.cycles - buffers_[id].ready_cycle >= config_.max_wait;
      if (!sampler_wants || due) {
        ready_.erase(it);
        stats_.forced_writes += sampler_wants;
        write_access(id);
      }
    }
  }
  if (busy_ > 0) {
    if (--busy_ == 0 && !reading_) buffers_[writing_].state = State::kFree;
    if (busy_ == 0) reading_ = false;
  } else if (sampler_wants) {
    granted = true;
    open_page_.fill(std::nullopt);  // the sampler's access moves every bank's page
  }
  stats_.sampler_granted += granted;
  stats_.sampler_lost += sampler_wants && !granted;
  ++stats_.cycles;
  return granted;
}

}  // namespace tmu::texram::video
