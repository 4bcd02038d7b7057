#include "volume/marcher.hpp"

#include <cmath>

#include "formats/formats.hpp"

namespace tmu::volume {

int32_t quantise(double voxels) {
  return static_cast<int32_t>(std::floor(voxels * (1 << kPosFrac) + 0.5));
}

int32_t wrap_pos(int64_t raw) {
  const int bits = formats::kVoxelPos.width();  // 26
  const int64_t m = int64_t{1} << bits;
  int64_t v = raw & (m - 1);
  if (v >= m / 2) v -= m;
  return static_cast<int32_t>(v);
}

bool ray_in_range(const Ray& ray) {
  using formats::kVoxelPos;
  using formats::kVoxelStep;
  if (ray.count > formats::kVoxelCount.max_raw()) return false;
  for (size_t a = 0; a < 3; ++a) {
    if (ray.start[a] < kVoxelPos.min_raw() || ray.start[a] > kVoxelPos.max_raw()) return false;
    if (ray.step[a] < kVoxelStep.min_raw() || ray.step[a] > kVoxelStep.max_raw()) return false;
    if (ray.count == 0) continue;
    const int64_t last = ray.start[a] + int64_t{ray.step[a]} * (ray.count - 1);
    if (last < kVoxelPos.min_raw() || last > kVoxelPos.max_raw()) return false;
  }
  return true;
}

void Marcher::advance() {
  for (size_t a = 0; a < 3; ++a) p_[a] = wrap_pos(int64_t{p_[a]} + ray_.step[a]);
  ++n_;
}

std::vector<Position> march(const Ray& ray) {
  std::vector<Position> out;
  out.reserve(ray.count);
  for (Marcher m(ray); !m.done(); m.advance()) out.push_back(m.position());
  return out;
}

}  // namespace tmu::volume
