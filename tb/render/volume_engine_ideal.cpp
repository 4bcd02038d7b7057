#include "render/volume_engine_ideal.hpp"

#include "volume/volume_ideal.hpp"

namespace tmu::render {
namespace {

class IdealVolumeEngine final : public VolumeUnitEngine {
 public:
  explicit IdealVolumeEngine(const volume::VoxelGrid& grid) : grid_(grid) {}

  std::vector<VolumeSample> cast(const std::vector<VolumeCommand>& commands) override {
    std::vector<VolumeSample> out;
    for (const VolumeCommand& c : commands) {
      for (uint32_t k = 0; k < c.ray.count; ++k) {
        const volume::Point p = volume::ideal_location({c.start.x, c.start.y, c.start.z},
                                                       {c.step.x, c.step.y, c.step.z}, c.first + k);
        const volume::IdealResample r = volume::ideal_resample(grid_, p);
        out.push_back({r.value, glm::dvec3(r.gradient[0], r.gradient[1], r.gradient[2])});
      }
      resamples_ += c.ray.count;
      ++rays_;
    }
    return out;
  }
  VolumeCounters counters() const override { return {rays_, resamples_, 0, 0, 0, 0}; }
  bool has_memory() const override { return false; }

 private:
  volume::VoxelGrid grid_;
  uint64_t rays_ = 0, resamples_ = 0;
};

}  // namespace

std::unique_ptr<VolumeUnitEngine> make_ideal_volume_engine(const volume::VoxelGrid& grid) {
  return std::make_unique<IdealVolumeEngine>(grid);
}

}  // namespace tmu::render
