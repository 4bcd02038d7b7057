#include "blocks/s2s_memory.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace tmu::tb {

namespace {

int words_of(const deflect::SphereGrid& grid) {
  return (deflect::kBlockEntries * deflect::entry_bits(grid) + 31) / 32;
}

}  // namespace

std::vector<uint32_t> pack_s2s_block(const deflect::S2sMap& map, uint32_t block) {
  const int bits = deflect::entry_bits(map.grid());
  std::vector<uint32_t> words(static_cast<size_t>(words_of(map.grid())), 0);
  const auto entries = map.block(block);
  for (int o = 0; o < deflect::kBlockEntries; ++o) {
    for (int b = 0; b < bits; ++b) {
      if ((entries[static_cast<size_t>(o)] >> b) & 1u) {
        const int at = o * bits + b;
        words[static_cast<size_t>(at / 32)] |= 1u << (at % 32);
      }
    }
  }
  return words;
}

S2sMemory::S2sMemory(std::shared_ptr<const deflect::S2sMap> map, S2sMemoryTiming timing,
                     uint64_t seed)
    : map_(std::move(map)), timing_(timing), rng_(seed) {
  if (timing_.latency < 1 || timing_.jitter < 0) {
    throw std::invalid_argument(fmt::format("map memory: latency {} (>= 1) and jitter {} (>= 0)",
                                            timing_.latency, timing_.jitter));
  }
  now_.resp_words.assign(static_cast<size_t>(words_of(map_->grid())), 0);
}

const S2sMemory::Inputs& S2sMemory::drive() {
  if (!drawn_) {
    now_.resp_valid = pending_ && due_cycle_ == cycle_;
    if (now_.resp_valid) {
      if (pending_block_ < map_->block_count()) {
        now_.resp_words = pack_s2s_block(*map_, pending_block_);
      } else {
        now_.resp_words.assign(now_.resp_words.size(), kPoison);
      }
    } else {
      for (uint32_t& w : now_.resp_words) w = static_cast<uint32_t>(rng_());
    }
    drawn_ = true;
  }
  return now_;
}

void S2sMemory::sample(bool req_valid, uint32_t block) {
  drive();  // this cycle's values, if nobody asked yet
  if (pending_) ++stall_cycles_;
  if (now_.resp_valid) pending_ = false;
  if (req_valid) {
    if (now_.resp_valid && error_.empty()) {
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
  drawn_ = false;
}

void MapAccessMonitor::sample(bool out_fire, uint64_t access) {
  if (!out_fire) return;
  // Code 3 means nothing and counts nowhere: the comparison of the access field fails it.
  const auto a = static_cast<deflect::MapAccess>(access);
  hits_ += a == deflect::MapAccess::kHit;
  misses_ += a == deflect::MapAccess::kMiss;
  bypasses_ += a == deflect::MapAccess::kBypass;
}

}  // namespace tmu::tb
