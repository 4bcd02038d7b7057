#include "blocks/clipmap/clip_memory.hpp"

#include <fmt/format.h>

#include "blocks/clipmap/clipmap_block.hpp"
#include "blocks/trilinear/texram_memory.hpp"

namespace tmu::tb {

using D = desc::clipmap;

Txn clip_access_request(const clipmap::BankAccess& a, bool write, int plane) {
  Txn t;
  for (size_t b = 0; b < 8; ++b) {
    const bool on = (a.enable >> b) & 1;
    t.f[D::mem_req_en + b] = on;
    // As the RTL drives the banks an access leaves out: a read shows address 0 + plane (its
    // plane-0 address register is 0 there), a write address 0 and data 0.
    t.f[D::mem_req_addr + b] = on ? a.address[b] : write ? 0 : static_cast<uint32_t>(plane);
    t.f[D::mem_req_wdata + b] = on && write ? a.data[b] : 0;
  }
  t.f[D::mem_req_we] = write;
  return t;
}

clipmap::BankAccess clip_access_of(const Txn& t, bool* write) {
  clipmap::BankAccess a;
  for (size_t b = 0; b < 8; ++b) {
    if (t.f[D::mem_req_en + b] == 0) continue;
    a.enable = static_cast<uint8_t>(a.enable | (1u << b));
    a.address[b] = static_cast<uint32_t>(t.f[D::mem_req_addr + b]);
    a.data[b] = static_cast<uint8_t>(t.f[D::mem_req_wdata + b]);
  }
  *write = t.f[D::mem_req_we] != 0;
  return a;
}

ClipMemory::ClipMemory(uint64_t seed) : rng_(seed) {}

void ClipMemory::configure(const Txn& cfg) {
  const clipmap::ClipGeometry g = clipmap_config_of(cfg).geometry();
  for (auto& bank : banks_) bank.assign(g.bank_cells(), 0);
}

void ClipMemory::drive(EnvPorts& ports) {
  if (!drawn_) {
    ready_ = cycle_ >= busy_until_;
    valid_ = !responses_.empty() && responses_.front().due_cycle == cycle_;
    data_ = valid_ ? responses_.front().data : rng_();  // garbage while not valid
    drawn_ = true;
  }
  ports.requests[0].ready = ready_;
  ChannelValue& resp = ports.responses[0];
  resp.valid = valid_;
  for (size_t b = 0; b < 8; ++b) resp.data.f[D::mem_resp_data + b] = (data_ >> (8 * b)) & 0xFF;
}

void ClipMemory::sample(const EnvPorts& ports) {
  if (valid_) responses_.pop_front();
  const ChannelValue& req = ports.requests[0];
  if (req.valid && req.ready) {
    bool write = false;
    const clipmap::BankAccess a = clip_access_of(req.data, &write);
    BankCells cells;
    uint64_t data = rng_();  // banks not read deliver garbage
    for (size_t b = 0; b < 8; ++b) {
      if (((a.enable >> b) & 1) == 0) continue;
      cells[b] = a.address[b];
      if (a.address[b] >= banks_[b].size()) {
        if (error_.empty()) {
          error_ =
              fmt::format("clip-map memory: {} of bank {} cell {} at cycle {}, beyond its {} cells",
                          write ? "write" : "read", b, a.address[b], cycle_, banks_[b].size());
        }
        continue;
      }
      if (write) {
        banks_[b][a.address[b]] = a.data[b];
      } else {
        data =
            (data & ~(uint64_t{0xFF} << (8 * b))) | (uint64_t{banks_[b][a.address[b]]} << (8 * b));
      }
    }
    if (a.enable == 0 && error_.empty()) {
      error_ = fmt::format("clip-map memory: the access at cycle {} enables no bank", cycle_);
    }
    const auto periods = static_cast<uint64_t>(pages_.access(cells));
    busy_until_ = cycle_ + periods;
    if (!write) responses_.push_back({cycle_ + periods, data});
  }
  ++cycle_;
  drawn_ = false;
}

Counters ClipMemory::counters() const { return page_counters(pages_.stats()); }

}  // namespace tmu::tb
