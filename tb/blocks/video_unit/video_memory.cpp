#include "blocks/video_unit/video_memory.hpp"

#include <fmt/format.h>

#include "blocks/video_unit/video_unit_block.hpp"
#include "formats/formats.hpp"

namespace tmu::tb {

using D = desc::video_unit;

namespace {

// The fields whose change starts a new video map (the waits do not).
bool same_map(const Txn& a, const Txn& b) {
  for (size_t f : {D::cfg_log2_w, D::cfg_log2_h, D::cfg_interlaced, D::cfg_four_planes,
                   D::cfg_base0, D::cfg_base1}) {
    if (a.f[f] != b.f[f]) return false;
  }
  return true;
}

}  // namespace

VideoMemory::VideoMemory(int latency, int jitter, uint64_t seed)
    : latency_(latency), jitter_(jitter), rng_(seed) {}

void VideoMemory::configure(const Txn& cfg) {
  if (same_map(cfg, map_)) return;
  map_ = cfg;
  for (auto& bank : banks_) bank.clear();
}

uint8_t VideoMemory::cell(unsigned bank, uint32_t address) const {
  const std::vector<uint8_t>& b = banks_[bank];
  return address < b.size() ? b[address] : 0;
}

void VideoMemory::drive(EnvPorts& ports) {
  ChannelValue& resp = ports.responses[0];
  resp.valid = !responses_.empty() && responses_.front().due_cycle == cycle_;
  for (uint32_t i = 0; i < kVideoUnitWordCells; ++i) {
    resp.data.f[D::mem_resp_data + i] = resp.valid ? responses_.front().cells[i] : rng_() & 0xFFu;
  }
}

void VideoMemory::sample(const EnvPorts& ports) {
  if (ports.responses[0].valid) responses_.pop_front();
  const ChannelValue& req = ports.requests[0];
  if (req.valid) {
    const auto bank = static_cast<unsigned>(req.data.f[D::mem_req_bank]);
    const auto addr = static_cast<uint32_t>(req.data.f[D::mem_req_addr]);
    if (uint64_t{addr} + kVideoUnitWordCells > (uint64_t{1} << formats::kBankAddr.width())) {
      if (error_.empty()) {
        error_ = fmt::format("video memory: a row at bank {} address {} ends beyond the bank", bank,
                             addr);
      }
    } else if (req.data.f[D::mem_req_write] != 0) {
      std::vector<uint8_t>& b = banks_[bank];
      if (b.size() < addr + kVideoUnitWordCells) b.resize(addr + kVideoUnitWordCells, 0);
      for (uint32_t i = 0; i < kVideoUnitWordCells; ++i) {
        if (req.data.f[D::mem_req_mask + i] != 0) {
          b[addr + i] = static_cast<uint8_t>(req.data.f[D::mem_req_data + i]);
        }
      }
    } else {
      Response r{};
      const uint64_t extra = jitter_ > 0 ? rng_() % static_cast<uint64_t>(jitter_ + 1) : 0;
      // In order, and never two in one cycle: a read waits behind the one before it.
      r.due_cycle = cycle_ + static_cast<uint64_t>(latency_) + extra;
      if (!responses_.empty() && r.due_cycle <= responses_.back().due_cycle) {
        r.due_cycle = responses_.back().due_cycle + 1;
      }
      for (uint32_t i = 0; i < kVideoUnitWordCells; ++i) r.cells[i] = cell(bank, addr + i);
      responses_.push_back(r);
    }
  }
  ++cycle_;
}

}  // namespace tmu::tb
