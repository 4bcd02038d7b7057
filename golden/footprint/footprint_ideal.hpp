// The ideal (double precision) footprint assembly: the golden model's rules (footprint.hpp)
// with exact lengths, logarithms, probe positions and samples (texram::ideal_sample), to
// measure what the setup's widths cost. Its own code throughout: it shares with golden only the
// q rule's definition (q_rule.hpp) and what the ideal trilinear unit shares. Two references the
// hardware does not build:
// - Direction::kEllipseAxis, the exact marching direction of eq. 12-18: the main axis of the
//   ellipse x^T (M^-1)^T M^-1 x = 1, M = [r1 r2]. Its semi-axes are M's singular values
//   a >= b, the axis the eigenvector of (M^-1)^T M^-1 det(M)^2 with the smaller eigenvalue
//   (b^2 ... a^2 of eq. 18); the probes march along a * (that unit vector), q = b.
// - supersampled(): the footprint parallelogram itself, box-filtered by a grid of trilinear
//   samples fine enough that each covers at most one level-0 texel (capped at 64 x 64).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>

#include "footprint/q_rule.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::footprint {

enum class Direction : uint8_t {
  kLongerSide,   // eq. 19-22: the longer of r1, r2 (what the hardware does)
  kEllipseAxis,  // eq. 12-18: the ellipse's main axis
};

struct IdealConfig {
  int log2_max_probes = 3;
  QRule q_rule = QRule::kHeights;  // kLongerSide only; the ellipse uses its minor semi-axis
  Direction direction = Direction::kLongerSide;
};

struct IdealPlan {
  int log2_n = 0;
  glm::dvec2 step{0};  // the marching vector r (probes at p + n r / 2N)
  double lambda = 0;   // -infinity for a point footprint
};
IdealPlan ideal_plan(glm::dvec2 r1, glm::dvec2 r2, const IdealConfig& config);

// A probe's sample at (u, v) in texels of level 0 and lambda in levels (below 0 where the
// footprint is smaller than a texel): RGBA, 0..255 each.
using IdealProbe = std::function<std::array<double, 4>(double u, double v, double lambda)>;

// The footprint's probes (ideal_plan) each sampled by `probe`, averaged.
std::array<double, 4> ideal_march(const IdealConfig& config, glm::dvec2 uv, glm::dvec2 r1,
                                  glm::dvec2 r2, const IdealProbe& probe);

// u, v in texels of level 0; the probes through the ideal trilinear unit. Returns RGBA, 0..255
// each.
std::array<double, 4> ideal_sample(const texram::IdealTexture& texture,
                                   const texram::SamplerConfig& sampler, const IdealConfig& config,
                                   glm::dvec2 uv, glm::dvec2 r1, glm::dvec2 r2, uint32_t shade);

std::array<double, 4> supersampled(const texram::IdealTexture& texture,
                                   const texram::SamplerConfig& sampler, glm::dvec2 uv,
                                   glm::dvec2 r1, glm::dvec2 r2, uint32_t shade);

}  // namespace tmu::footprint
