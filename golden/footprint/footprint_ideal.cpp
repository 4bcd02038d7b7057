#include "footprint/footprint_ideal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tmu::footprint {
namespace {

constexpr double kMinusInfinity = -std::numeric_limits<double>::infinity();
// The ideal trilinear unit takes a finite lambda; anything below level 0 magnifies.
constexpr double kFinestLambda = -64.0;

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

}  // namespace

IdealPlan ideal_plan(glm::dvec2 r1, glm::dvec2 r2, const IdealConfig& config) {
  IdealPlan p;
  const double l1 = glm::length(r1), l2 = glm::length(r2);
  const double area = std::abs(cross(r1, r2));
  double longer = 0, q = 0;
  if (config.direction == Direction::kEllipseAxis) {
    // Singular values of M = [r1 r2] from the eigenvalues of M^T M (the same as those of
    // M M^T, whose eigenvector with the larger eigenvalue is the ellipse's main axis).
    const double a11 = r1.x * r1.x + r2.x * r2.x, a12 = r1.x * r1.y + r2.x * r2.y,
                 a22 = r1.y * r1.y + r2.y * r2.y;  // M M^T
    const double mean = (a11 + a22) / 2, diff = (a11 - a22) / 2;
    const double radius = std::hypot(diff, a12);
    const double big = mean + radius;
    longer = std::sqrt(std::max(big, 0.0));
    q = longer > 0 ? area / longer : 0;  // a b = |det M|
    // Eigenvector of M M^T for `big`: (a12, big - a11) or (big - a22, a12), the better
    // conditioned one.
    glm::dvec2 axis = std::abs(big - a11) > std::abs(big - a22) ? glm::dvec2(a12, big - a11)
                                                                : glm::dvec2(big - a22, a12);
    if (glm::length(axis) == 0) axis = {1, 0};  // a circle (or a point): any axis
    p.step = glm::normalize(axis) * longer;
  } else {
    longer = std::max(l1, l2);
    p.step = l2 > l1 ? r2 : r1;
    q = config.q_rule == QRule::kHeights ? (longer > 0 ? area / longer : 0) : std::min(l1, l2);
  }
  if (longer == 0) {
    p.lambda = kMinusInfinity;
    return p;
  }
  const double log2_longer = std::log2(longer);
  const int kmax = config.log2_max_probes;
  int k =
      q > 0 ? static_cast<int>(std::min<double>(kmax, std::floor(log2_longer - std::log2(q) + 0.5)))
            : kmax;
  k = std::min(k,
               std::max(0, static_cast<int>(std::floor(log2_longer)) + 2));  // >= 1/4 texel apart
  p.log2_n = k;
  const double spread = log2_longer - k;
  p.lambda = q > 0 ? std::max(std::log2(q), spread) : spread;
  return p;
}

std::array<double, 4> ideal_march(const IdealConfig& config, glm::dvec2 uv, glm::dvec2 r1,
                                  glm::dvec2 r2, const IdealProbe& probe) {
  const IdealPlan p = ideal_plan(r1, r2, config);
  const int n = 1 << p.log2_n;
  const double lambda = std::max(p.lambda, kFinestLambda);
  std::array<double, 4> sum{};
  for (int i = 0; i < n; ++i) {
    const double t = (2.0 * i - (n - 1)) / (2.0 * n);
    const glm::dvec2 at = uv + t * p.step;
    const auto c = probe(at.x, at.y, lambda);
    for (size_t ch = 0; ch < 4; ++ch) sum[ch] += c[ch];
  }
  for (double& s : sum) s /= n;
  return sum;
}

std::array<double, 4> ideal_sample(const texram::IdealTexture& texture,
                                   const texram::SamplerConfig& sampler, const IdealConfig& config,
                                   glm::dvec2 uv, glm::dvec2 r1, glm::dvec2 r2, uint32_t shade) {
  return ideal_march(config, uv, r1, r2, [&](double u, double v, double lambda) {
    return texram::ideal_sample(texture, sampler, u, v, lambda, shade);
  });
}

std::array<double, 4> supersampled(const texram::IdealTexture& texture,
                                   const texram::SamplerConfig& sampler, glm::dvec2 uv,
                                   glm::dvec2 r1, glm::dvec2 r2, uint32_t shade) {
  static constexpr int kMaxGrid = 64;
  const auto grid = [](double length) {
    return std::clamp(static_cast<int>(std::ceil(length)), 1, kMaxGrid);
  };
  const int g1 = grid(glm::length(r1)), g2 = grid(glm::length(r2));
  // Each sample covers r1 / g1 by r2 / g2: its own footprint picks the level.
  const double cell = std::max(glm::length(r1) / g1, glm::length(r2) / g2);
  const double lambda = cell > 0 ? std::max(std::log2(cell), kFinestLambda) : kFinestLambda;
  std::array<double, 4> sum{};
  for (int j = 0; j < g2; ++j) {
    for (int i = 0; i < g1; ++i) {
      const glm::dvec2 at = uv + ((i + 0.5) / g1 - 0.5) * r1 + ((j + 0.5) / g2 - 0.5) * r2;
      const auto c = texram::ideal_sample(texture, sampler, at.x, at.y, lambda, shade);
      for (size_t ch = 0; ch < 4; ++ch) sum[ch] += c[ch];
    }
  }
  for (double& s : sum) s /= g1 * g2;
  return sum;
}

}  // namespace tmu::footprint
