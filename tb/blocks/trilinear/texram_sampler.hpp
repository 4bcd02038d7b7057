// The golden trilinear unit over a run of items, as the blocks with its ports run it
// (trilinear; footprint, one sample per probe): the configuration in effect, the CLUT as the
// items wrote it, the page model of the banks (running on across textures, as the memory's),
// and every access of a sample as the request the unit makes (texram::sample's arithmetic,
// golden/texram/trilinear.hpp).
#pragma once

#include <bitset>
#include <memory>
#include <string>

#include "blocks/trilinear/texram_setup.hpp"
#include "blocks/trilinear/texram_textures.hpp"
#include "harness/model.hpp"
#include "texram/page_model.hpp"
#include "texram/trilinear.hpp"

namespace tmu::tb {

class TexramSampler {
 public:
  // `block` names the block in errors.
  TexramSampler(std::string block, std::shared_ptr<const TexramTextures> textures);

  // A new environment: the setup's configuration and texture (the CLUT and the pages stay).
  void configure(const TexramSetup& setup);
  void write_clut(uint8_t index, uint32_t rgba);
  // One sample, RGBA8888; its accesses go to `sink` as requests of channel 0. Throws
  // std::runtime_error for a sample before the configuration, or of an index or CCC texture
  // before every CLUT entry was written (the CLUT is a RAM without reset).
  uint32_t sample(const texram::Request& request, Sink& sink);
  const texram::SamplerConfig& config() const { return setup_.config; }
  // The memory's counters (page_counters).
  Counters counters() const;

 private:
  std::string block_;
  std::shared_ptr<const TexramTextures> textures_;
  TexramSetup setup_;
  std::shared_ptr<const texram::TexramTexture> texture_;
  texram::Clut32 clut_{};
  std::bitset<256> written_;
  texram::PageModel pages_;
};

}  // namespace tmu::tb
