#include "render/volume_engine.hpp"

#include <stdexcept>

#include "render/volume_engine_block.hpp"
#include "render/volume_engine_ideal.hpp"
#include "texram/page_model.hpp"

namespace tmu::render {
namespace {

class GoldenVolumeEngine final : public VolumeUnitEngine {
 public:
  GoldenVolumeEngine(const volume::VoxelGrid& grid, const volume::Config& config)
      : memory_(volume::load(grid)), config_(config) {}

  std::vector<VolumeSample> cast(const std::vector<VolumeCommand>& commands) override {
    std::vector<VolumeSample> out;
    for (const VolumeCommand& c : commands) {
      for (const volume::Resample& r : volume::cast(memory_, config_, c.ray, &pages_)) {
        out.push_back(
            {static_cast<double>(r.value), glm::dvec3(r.gradient[0], r.gradient[1], r.gradient[2]) /
                                               static_cast<double>(1 << volume::kGradFrac)});
      }
      resamples_ += c.ray.count;
      ++rays_;
    }
    return out;
  }

  VolumeCounters counters() const override {
    const texram::PageStats& s = pages_.stats();
    return {rays_, resamples_, s.accesses, s.bank_reads, s.page_faults, s.slow_accesses};
  }
  bool has_memory() const override { return true; }

 private:
  volume::VolumeMemory memory_;
  volume::Config config_;
  texram::PageModel pages_;
  uint64_t rays_ = 0, resamples_ = 0;
};

}  // namespace

double VolumeCounters::seconds() const {
  return static_cast<double>(accesses + slow_accesses) * texram::kAccessNs * 1e-9;
}

VolumeCounters& VolumeCounters::operator+=(const VolumeCounters& o) {
  rays += o.rays;
  resamples += o.resamples;
  accesses += o.accesses;
  bank_reads += o.bank_reads;
  page_faults += o.page_faults;
  slow_accesses += o.slow_accesses;
  return *this;
}

VolumePieceCheck& VolumePieceCheck::operator+=(const VolumePieceCheck& o) {
  if (against.empty()) against = o.against;
  pieces += o.pieces;
  outputs += o.outputs;
  requests += o.requests;
  differing_pieces += o.differing_pieces;
  for (const std::string& f : o.first) {
    if (first.size() < 5) first.push_back(f);
  }
  return *this;
}

std::unique_ptr<VolumeUnitEngine> make_volume_engine(Level level, const volume::VoxelGrid& grid,
                                                     const volume::Config& config,
                                                     const VolumeEngineOptions& options) {
  if (level == Level::kIdeal) return make_ideal_volume_engine(grid);
  if (level == Level::kGolden) return std::make_unique<GoldenVolumeEngine>(grid, config);
  return make_block_volume_engine(level, grid, config, options);
}

}  // namespace tmu::render
