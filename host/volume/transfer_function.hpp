// The transfer function of a raw volume (000 §13: raw data is classified by the host): points
// of value -> colour and opacity, linear between them and constant beyond the first and the
// last. Values are voxel values (0..255, real: the ideal's resamples are not integers), colours
// 0..1, opacity per voxel of path length (corrected for the ray's step by the compositor).
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace tmu::host {

struct TransferPoint {
  double value = 0;      // 0..255
  glm::dvec3 colour{1};  // 0..1
  double opacity = 0;    // 0..1, per voxel of path length
};

struct Classified {
  glm::dvec3 colour{0};
  double opacity = 0;
};

class TransferFunction {
 public:
  TransferFunction() = default;
  // Points in strictly increasing value order (the scene parser checks it); at least one.
  explicit TransferFunction(std::vector<TransferPoint> points);
  Classified operator()(double value) const;
  const std::vector<TransferPoint>& points() const { return points_; }

 private:
  std::vector<TransferPoint> points_;
};

}  // namespace tmu::host
