#include "blocks/deflect/s2s_memory.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "blocks/deflect/deflect_block.hpp"

namespace tmu::tb {

using D = desc::deflect;

S2sMemory::S2sMemory(std::shared_ptr<const deflect::S2sMap> map, S2sMemoryTiming timing,
                     uint64_t seed)
    : map_(std::move(map)), timing_(timing), rng_(seed) {
  if (timing_.latency < 1 || timing_.jitter < 0) {
    throw std::invalid_argument(fmt::format("map memory: latency {} (>= 1) and jitter {} (>= 0)",
                                            timing_.latency, timing_.jitter));
  }
}

void S2sMemory::drive(EnvPorts& ports) {
  ChannelValue& resp = ports.responses[0];
  resp.valid = pending_ && due_cycle_ == cycle_;
  for (int o = 0; o < deflect::kBlockEntries; ++o) {
    uint64_t& entry = resp.data.f[static_cast<size_t>(D::map_resp_data + o)];
    if (!resp.valid) {
      entry = rng_();
    } else if (pending_block_ < map_->block_count()) {
      entry = map_->block(pending_block_)[static_cast<size_t>(o)];
    } else {
      entry = kPoison;
    }
  }
}

void S2sMemory::sample(const EnvPorts& ports) {
  const bool resp_valid = ports.responses[0].valid;
  if (pending_) ++stall_cycles_;
  if (resp_valid) pending_ = false;
  const ChannelValue& req = ports.requests[0];
  if (req.valid) {
    const auto block = static_cast<uint32_t>(req.data.f[D::map_req_block]);
    if (resp_valid && error_.empty()) {
      error_ = fmt::format(
          "map memory: request for block {} at cycle {}, the cycle its predecessor's response "
          "arrives (one outstanding request)",
          block, cycle_);
    } else if (pending_ && error_.empty()) {
      error_ =
          fmt::format("map memory: request for block {} at cycle {} while block {} is outstanding",
                      block, cycle_, pending_block_);
    }
    if (block >= map_->block_count() && error_.empty()) {
      error_ = fmt::format("map memory: request for block {} at cycle {}, beyond the map's {}",
                           block, cycle_, map_->block_count());
    }
    ++fetches_;
    pending_ = true;
    pending_block_ = block;
    const uint64_t extra =
        timing_.jitter > 0 ? rng_() % static_cast<uint64_t>(timing_.jitter + 1) : 0;
    due_cycle_ = cycle_ + static_cast<uint64_t>(timing_.latency) + extra;
  }
  ++cycle_;
}

}  // namespace tmu::tb
