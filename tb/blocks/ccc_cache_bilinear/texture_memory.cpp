#include "blocks/ccc_cache_bilinear/texture_memory.hpp"

#include <fmt/format.h>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_block.hpp"

namespace tmu::tb {

using D = desc::ccc_cache_bilinear;

TextureMemory::TextureMemory(TextureOf texture_of, uint64_t seed)
    : texture_of_(std::move(texture_of)), rng_(seed) {}

void TextureMemory::drive(EnvPorts& ports) {
  const uint64_t r = rng_();
  ports.requests[0].ready = r % 100 < 80;
  ChannelValue& resp = ports.responses[0];
  resp.valid = pending_ && due_cycle_ == cycle_;
  // Garbage while not valid: a unit that samples the bus at the wrong time fails.
  resp.data.f[D::mem_resp_block] = resp.valid ? pending_word_ : static_cast<uint32_t>(r >> 32);
}

void TextureMemory::sample(const EnvPorts& ports) {
  if (ports.responses[0].valid) pending_ = false;
  const ChannelValue& req = ports.requests[0];
  if (req.valid && req.ready) {
    const auto address = static_cast<uint32_t>(req.data.f[D::mem_req_addr]);
    if (pending_ && error_.empty()) {
      error_ =
          fmt::format("texture memory: request for block {} at cycle {} while one is outstanding",
                      address, cycle_);
    }
    pending_ = true;
    due_cycle_ = cycle_ + 1 + rng_() % 6;
    if (texture_ && address < texture_->blocks.size()) {
      pending_word_ = texture_->blocks[address];
    } else {
      pending_word_ = kPoison;
      if (error_.empty()) {
        error_ = fmt::format(
            "texture memory: read of block {} at cycle {}, beyond the texture's {} blocks", address,
            cycle_, texture_ ? texture_->blocks.size() : 0);
      }
    }
  }
  ++cycle_;
}

}  // namespace tmu::tb
