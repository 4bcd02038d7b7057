// Front-to-back alpha compositing with early termination (000 §13: the host blends; Levoy 1990
// for the termination): host work, named so in the render report.
//
//   C += (1 - A) c,  A += (1 - A) a        (c the opacity-weighted colour of a resample)
//   pixel = C + (1 - A) background
//
// Early termination at alpha t: a ray stops once A >= t. Everything behind would add at most
// (1 - A) of full scale to C and take as much of the background's share away, so a terminated
// pixel differs from the unterminated one by at most 1 - A <= 1 - t per channel (colours 0..1;
// t = 255/256, the default, keeps it within one 8-bit level before rounding). Termination with
// t = 1 stops only at full opacity and changes nothing.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "volume/sample_shading.hpp"

namespace tmu::host {

class RayCompositor {
 public:
  // `stop_alpha`: the termination threshold t (nullopt: every resample is composited).
  explicit RayCompositor(std::optional<double> stop_alpha = std::nullopt) : stop_(stop_alpha) {}
  void add(const Contribution& c) {
    colour_ += (1 - alpha_) * c.colour;
    alpha_ += (1 - alpha_) * c.alpha;
    ++added_;
  }
  bool terminated() const { return stop_ && alpha_ >= *stop_; }
  const glm::dvec3& colour() const { return colour_; }
  double alpha() const { return alpha_; }
  uint64_t added() const { return added_; }
  glm::dvec3 over(const glm::dvec3& background) const {
    return colour_ + (1 - alpha_) * background;
  }

 private:
  std::optional<double> stop_;
  glm::dvec3 colour_{0};
  double alpha_ = 0;
  uint64_t added_ = 0;
};

}  // namespace tmu::host
