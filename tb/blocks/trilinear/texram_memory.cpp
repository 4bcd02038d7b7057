#include "blocks/trilinear/texram_memory.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "blocks/trilinear/trilinear_block.hpp"

namespace tmu::tb {

using D = desc::trilinear;
static_assert(formats::kBanks == 8, "the memory rows have eight banks");

std::vector<BankAccess> sample_accesses(const texram::SamplePlan& plan) {
  std::vector<BankAccess> out;
  if (std::none_of(plan.bank_address.begin(), plan.bank_address.end(),
                   [](const auto& a) { return a.has_value(); })) {
    return out;
  }
  for (int p = 0; p < plan.planes; ++p) {
    BankAccess a;
    a.plane = p;
    for (size_t b = 0; b < 8; ++b) {
      if (plan.bank_address[b]) a.cells[b] = *plan.bank_address[b] + static_cast<uint32_t>(p);
    }
    out.push_back(a);
  }
  return out;
}

Txn access_request(const BankAccess& access) {
  Txn t;
  for (size_t b = 0; b < 8; ++b) {
    t.f[D::mem_req_en + b] = access.cells[b].has_value();
    t.f[D::mem_req_addr + b] = access.cells[b].value_or(static_cast<uint32_t>(access.plane));
  }
  return t;
}

Counters page_counters(const texram::PageStats& s) {
  return {{"accesses", s.accesses},
          {"bank_reads", s.bank_reads},
          {"page_faults", s.page_faults},
          {"slow_accesses", s.slow_accesses}};
}

TexramMemory::TexramMemory(TextureOf texture_of, uint64_t seed, bool empty_accesses,
                           const texram::OpenPages& open_pages)
    : texture_of_(std::move(texture_of)),
      empty_accesses_(empty_accesses),
      rng_(seed),
      pages_(open_pages) {}

void TexramMemory::drive(EnvPorts& ports) {
  if (!drawn_) {
    ready_ = cycle_ >= busy_until_;
    valid_ = !responses_.empty() && responses_.front().due_cycle == cycle_;
    // Garbage while not valid: a unit that samples the bus at the wrong time fails.
    data_ = valid_ ? responses_.front().data : rng_();
    drawn_ = true;
  }
  ports.requests[0].ready = ready_;
  ChannelValue& resp = ports.responses[0];
  resp.valid = valid_;
  for (size_t b = 0; b < 8; ++b) resp.data.f[D::mem_resp_data + b] = (data_ >> (8 * b)) & 0xFF;
}

void TexramMemory::sample(const EnvPorts& ports) {
  if (valid_) responses_.pop_front();
  const ChannelValue& req = ports.requests[0];
  if (req.valid && req.ready) {
    BankCells read;
    uint64_t data = rng_();  // banks not read deliver garbage
    for (size_t b = 0; b < 8; ++b) {
      if (req.data.f[D::mem_req_en + b] == 0) continue;
      const auto address = static_cast<uint32_t>(req.data.f[D::mem_req_addr + b]);
      read[b] = address;
      uint8_t byte = kPoison;
      if (texture_ && address < texture_->banks[b].size()) {
        byte = texture_->banks[b][address];
      } else if (error_.empty()) {
        error_ =
            fmt::format("texram memory: read of bank {} cell {} at cycle {}, beyond its {} cells",
                        b, address, cycle_, texture_ ? texture_->banks[b].size() : 0);
      }
      data = (data & ~(uint64_t{0xFF} << (8 * b))) | (uint64_t{byte} << (8 * b));
    }
    if (!empty_accesses_ &&
        std::none_of(read.begin(), read.end(), [](const auto& a) { return a.has_value(); }) &&
        error_.empty()) {
      error_ = fmt::format("texram memory: the access at cycle {} reads no bank", cycle_);
    }
    const auto periods = static_cast<uint64_t>(pages_.access(read));
    busy_until_ = cycle_ + periods;
    responses_.push_back({cycle_ + periods, data});
  }
  ++cycle_;
  drawn_ = false;
}

}  // namespace tmu::tb
