#include "blocks/trilinear/texram_sampler.hpp"

#include <stdexcept>

#include "blocks/trilinear/texram_memory.hpp"

namespace tmu::tb {

TexramSampler::TexramSampler(std::string block, std::shared_ptr<const TexramTextures> textures)
    : block_(std::move(block)), textures_(std::move(textures)) {}

void TexramSampler::configure(const TexramSetup& setup) {
  texture_ = textures_->texture_of(setup);
  setup_ = setup;
}

void TexramSampler::write_clut(uint8_t index, uint32_t rgba) {
  clut_[index] = rgba;
  written_.set(index);
}

uint32_t TexramSampler::sample(const texram::Request& request, Sink& sink) {
  if (!texture_) throw std::runtime_error(block_ + ": a sample before the configuration");
  const texram::SamplerConfig& c = setup_.config;
  if (uses_clut(c.kind) && !written_.all()) {
    throw std::runtime_error(block_ + ": a sample of an " + std::string(texram::name(c.kind)) +
                             " texture before all 256 CLUT entries are written (the CLUT is a "
                             "RAM without reset: load it first)");
  }
  const texram::SamplePlan plan = texram::plan_sample(texture_->geometry, c, request);
  for (const BankAccess& a : sample_accesses(plan)) {
    sink.request(0, access_request(a));
    pages_.access(a.cells);
  }
  const texram::AccessData data = texram::read_access(*texture_, plan);
  std::array<std::array<uint32_t, 4>, 2> colours{};
  for (size_t j = 0; j < static_cast<size_t>(plan.levels_read); ++j) {
    for (size_t k = 0; k < static_cast<size_t>(plan.taps_per_level); ++k) {
      colours[j][k] = texram::tap_colour(plan.taps[j][k], data, c.kind, c, clut_);
    }
  }
  return texram::combine(texram::blend_taps(plan, colours, c.widths), c, request.shade);
}

Counters TexramSampler::counters() const { return page_counters(pages_.stats()); }

}  // namespace tmu::tb
