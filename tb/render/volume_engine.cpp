#include "render/volume_engine.hpp"

#include <stdexcept>

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
    }
    return out;
  }

  VolumeCounters counters() const override {
    const texram::PageStats& s = pages_.stats();
    return {resamples_, s.accesses, s.bank_reads, s.page_faults, s.slow_accesses};
  }
  bool has_memory() const override { return true; }

 private:
  volume::VolumeMemory memory_;
  volume::Config config_;
  texram::PageModel pages_;
  uint64_t resamples_ = 0;
};

}  // namespace

double VolumeCounters::seconds() const {
  return static_cast<double>(accesses + slow_accesses) * texram::kAccessNs * 1e-9;
}

VolumeCounters& VolumeCounters::operator+=(const VolumeCounters& o) {
  resamples += o.resamples;
  accesses += o.accesses;
  bank_reads += o.bank_reads;
  page_faults += o.page_faults;
  slow_accesses += o.slow_accesses;
  return *this;
}

void require_volume_engine(Level level) {
  if (level == Level::kHls || level == Level::kRtl) {
    throw std::runtime_error(
        "volume unit: no hls/rtl engine yet (the co-simulated block is being built on branch "
        "volume-block; it plugs in at tb/render/volume_engine.hpp); use --engine ideal or golden");
  }
}

std::unique_ptr<VolumeUnitEngine> make_volume_engine(Level level, const volume::VoxelGrid& grid,
                                                     const volume::Config& config) {
  require_volume_engine(level);
  if (level == Level::kIdeal) return make_ideal_volume_engine(grid);
  return std::make_unique<GoldenVolumeEngine>(grid, config);
}

}  // namespace tmu::render
