#include "volume/sample_shading.hpp"

#include <algorithm>
#include <cmath>

#include "raster/shading.hpp"

namespace tmu::host {

SampleShading::SampleShading(const TransferFunction& transfer, const std::vector<Light>& lights,
                             double step, const std::array<uint32_t, 3>& size)
    : transfer_(transfer),
      lights_(lights),
      step_(step),
      centre_(glm::dvec3(size[0] - 1, size[1] - 1, size[2] - 1) / 2.0),
      scale_((std::max({size[0], size[1], size[2]}) - 1) / 2.0) {}

double SampleShading::corrected(double opacity) const {
  if (opacity >= 1) return 1;
  return 1 - std::pow(1 - opacity, step_);
}

glm::dvec3 SampleShading::light(const glm::dvec3& gradient, const glm::dvec3& position) const {
  if (lights_.empty()) return glm::dvec3(1);
  const double length = glm::length(gradient);
  if (length == 0) {
    glm::dvec3 sum(0);
    for (const Light& l : lights_) sum += l.colour;
    return glm::clamp(sum, 0.0, 1.0);
  }
  return shade(lights_, -gradient / length, (position - centre_) / scale_);
}

Contribution SampleShading::raw(double value, const glm::dvec3& gradient,
                                const glm::dvec3& position) const {
  const Classified c = transfer_(value);
  const double alpha = corrected(c.opacity);
  if (alpha == 0) return {};
  return {c.colour * light(gradient, position) * alpha, alpha};
}

Contribution SampleShading::rgba(const std::array<double, 4>& components) const {
  const double opacity = components[3] / 255;
  if (opacity <= 0) return {};
  const double alpha = corrected(opacity);
  // The colour is opacity-weighted for one voxel of path; per step it is weighted by the
  // corrected opacity instead (and never above it: the components are rounded separately).
  glm::dvec3 colour;
  for (int c = 0; c < 3; ++c)
    colour[c] = std::min(components[static_cast<size_t>(c)] / 255, opacity) / opacity * alpha;
  return {colour, alpha};
}

}  // namespace tmu::host
