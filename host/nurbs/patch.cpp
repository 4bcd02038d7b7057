// invalid_reason: the first problem with a patch, named by field, in the order a reader checks:
// degrees, counts, knot vectors (size, finite, order, domain), then points and weights.
#include "nurbs/patch.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace tmu::host::nurbs {
namespace {

// One direction's degree, count and knots; `axis` is "s" or "t".
std::string direction_problem(const char* axis, int degree, int count,
                              const std::vector<double>& knots) {
  if (degree < 1 || degree > 3) {
    return fmt::format("degree_{}: {} is out of range 1..3", axis, degree);
  }
  if (count < degree + 1) {
    return fmt::format("count_{}: {} control points, expected at least degree_{} + 1 = {}", axis,
                       count, axis, degree + 1);
  }
  const std::size_t expected = static_cast<std::size_t>(count) + degree + 1;
  if (knots.size() != expected) {
    return fmt::format("knots_{}: {} knots, expected count_{} + degree_{} + 1 = {}", axis,
                       knots.size(), axis, axis, expected);
  }
  for (std::size_t k = 0; k < knots.size(); ++k) {
    if (!std::isfinite(knots[k])) {
      return fmt::format("knots_{}[{}]: {} is not finite", axis, k, knots[k]);
    }
  }
  for (std::size_t k = 1; k < knots.size(); ++k) {
    if (knots[k] < knots[k - 1]) {
      return fmt::format("knots_{}: not non-decreasing at index {} ({} after {})", axis, k,
                         knots[k], knots[k - 1]);
    }
  }
  if (knots[degree] == knots[count]) {
    return fmt::format("knots_{}: empty parameter domain (knots_{}[{}] = knots_{}[{}] = {})", axis,
                       axis, degree, axis, count, knots[count]);
  }
  return "";
}

}  // namespace

std::string invalid_reason(const Patch& patch) {
  if (auto why = direction_problem("s", patch.degree_s, patch.count_s, patch.knots_s);
      !why.empty()) {
    return why;
  }
  if (auto why = direction_problem("t", patch.degree_t, patch.count_t, patch.knots_t);
      !why.empty()) {
    return why;
  }
  // Counts are at least 2 here; the product in 64 bits cannot overflow.
  const auto expected =
      static_cast<std::size_t>(static_cast<int64_t>(patch.count_s) * patch.count_t);
  if (patch.points.size() != expected) {
    return fmt::format("points: {} control points, expected count_s * count_t = {}",
                       patch.points.size(), expected);
  }
  if (patch.weights.size() != expected) {
    return fmt::format("weights: {} weights, expected count_s * count_t = {}", patch.weights.size(),
                       expected);
  }
  for (std::size_t k = 0; k < expected; ++k) {
    const glm::dvec3& p = patch.points[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return fmt::format("points[{}]: ({}, {}, {}) is not finite", k, p.x, p.y, p.z);
    }
  }
  for (std::size_t k = 0; k < expected; ++k) {
    const double w = patch.weights[k];
    if (!std::isfinite(w)) return fmt::format("weights[{}]: {} is not finite", k, w);
    if (!(w > 0)) return fmt::format("weights[{}]: {} must be > 0", k, w);
  }
  return "";
}

}  // namespace tmu::host::nurbs
