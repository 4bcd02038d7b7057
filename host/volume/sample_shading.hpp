// What one resample adds to its ray (host work: 000 §13 leaves classification, shading and
// blending to the host). Raw data: the transfer function at the resampled value gives colour
// and opacity, the colour is shaded by the scene's lights (scenes/README.md's rule, the one of
// every scene) at the normal the gradient gives; pre-classified (rgba) data: the four resampled
// components are already the opacity-weighted colour and the opacity. Either way the opacity,
// given per voxel of path, is corrected for the ray's step: a = 1 - (1 - a_1)^step, and the
// colour weighted by it.
//
// The normal: -gradient / |gradient|, the direction in which the values fall: a denser object
// (the sphere's inside, bone in a scan) is lit on the side facing the light. Where the gradient
// is zero there is no surface to shade: the sample takes the lights' full colour (as if it faced
// every light), as an unshaded sample would.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.hpp"
#include "volume/transfer_function.hpp"

namespace tmu::host {

// One resample's contribution: opacity-weighted colour and opacity, for one step of the ray.
struct Contribution {
  glm::dvec3 colour{0};
  double alpha = 0;
};

class SampleShading {
 public:
  // `size`: the volume's, to place a sample in the world for point lights.
  SampleShading(const TransferFunction& transfer, const std::vector<Light>& lights, double step,
                const std::array<uint32_t, 3>& size);
  // A raw resample: value 0..255, gradient in voxel values per voxel, position in voxels.
  Contribution raw(double value, const glm::dvec3& gradient, const glm::dvec3& position) const;
  // A pre-classified resample: R, G, B (opacity-weighted) and A, 0..255 each.
  Contribution rgba(const std::array<double, 4>& components) const;
  // The light a sample takes at this gradient (the shade, 0..1 per channel).
  glm::dvec3 light(const glm::dvec3& gradient, const glm::dvec3& position) const;

 private:
  double corrected(double opacity) const;  // per voxel -> per step
  TransferFunction transfer_;
  std::vector<Light> lights_;
  double step_;
  glm::dvec3 centre_;
  double scale_;  // voxels per world unit
};

}  // namespace tmu::host
