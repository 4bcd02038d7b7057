#include "volume/ray_sets.hpp"

#include <array>
#include <stdexcept>

namespace tmu::volume {

std::vector<Ray> figure_rays(const std::string& set, uint32_t nx, uint32_t ny, uint32_t nz) {
  std::vector<Ray> rays;
  constexpr int32_t kHalf = 1 << (kPosFrac - 1);
  const auto at = [](uint32_t i) { return static_cast<int32_t>(i << kPosFrac) + kHalf; };
  if (set == "x") {
    for (uint32_t k = 0; k < nz; ++k) {
      for (uint32_t j = 0; j < ny; ++j)
        rays.push_back({{kHalf, at(j), at(k)}, {1 << kPosFrac, 0, 0}, nx});
    }
    return rays;
  }
  if (set != "z" && set != "oblique") {
    throw std::invalid_argument("volume ray set '" + set + "' (sets: z, x, oblique)");
  }
  const std::array<int32_t, 3> step =
      set == "z" ? std::array<int32_t, 3>{0, 0, 1 << kPosFrac}
                 : std::array<int32_t, 3>{1 << (kPosFrac - 3), 1 << (kPosFrac - 4), 1 << kPosFrac};
  for (uint32_t j = 0; j < ny; ++j) {
    for (uint32_t i = 0; i < nx; ++i) rays.push_back({{at(i), at(j), kHalf}, step, nz});
  }
  return rays;
}

}  // namespace tmu::volume
