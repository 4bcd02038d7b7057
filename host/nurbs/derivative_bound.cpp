// derivative_bound(): the per-span bound derived in patch.hpp, computed in s on the patch and in t
// on its transpose, so that one function states the formula.
#include <algorithm>
#include <cmath>

#include "nurbs/patch.hpp"

namespace tmu::host::nurbs {
namespace {

// The patch with s and t exchanged (point (i, j) becomes (j, i)).
Patch transposed(const Patch& patch) {
  Patch out;
  out.degree_s = patch.degree_t;
  out.degree_t = patch.degree_s;
  out.count_s = patch.count_t;
  out.count_t = patch.count_s;
  out.knots_s = patch.knots_t;
  out.knots_t = patch.knots_s;
  out.points.resize(patch.points.size());
  out.weights.resize(patch.weights.size());
  for (int j = 0; j < patch.count_t; ++j) {
    for (int i = 0; i < patch.count_s; ++i) {
      out.points[j + out.count_s * i] = patch.point(i, j);
      out.weights[j + out.count_s * i] = patch.weight(i, j);
    }
  }
  return out;
}

// The bound of ||dS/ds|| on span a (along s) x b (along t): the local net is i in a-p..a,
// j in b-q..b; each row j is divided by its own smallest weight (the mediant step of patch.hpp).
double span_bound_s(const Patch& patch, int a, int b) {
  const int p = patch.degree_s, q = patch.degree_t;
  // R(P): the largest distance from P to a local control point, which bounds ||P - S||.
  auto reach = [&](const glm::dvec3& from) {
    double r = 0;
    for (int j = b - q; j <= b; ++j) {
      for (int i = a - p; i <= a; ++i) r = std::max(r, glm::length(patch.point(i, j) - from));
    }
    return r;
  };
  double bound = 0;
  for (int j = b - q; j <= b; ++j) {
    double row_w_min = patch.weight(a - p, j);
    for (int i = a - p; i <= a; ++i) row_w_min = std::min(row_w_min, patch.weight(i, j));
    for (int i = a - p; i < a; ++i) {
      const double du = patch.knots_s[i + p + 1] - patch.knots_s[i + 1];  // >= the span's length
      const glm::dvec3 &p0 = patch.point(i, j), &p1 = patch.point(i + 1, j);
      const double w0 = patch.weight(i, j), w1 = patch.weight(i + 1, j);
      const double dp = glm::length(p1 - p0), dw = std::abs(w1 - w0);
      const double difference = std::min(w0 * dp + dw * reach(p1), w1 * dp + dw * reach(p0));
      bound = std::max(bound, p * difference / (du * row_w_min));
    }
  }
  return bound;
}

double bound_s(const Patch& patch) {
  double bound = 0;
  for (int b = patch.degree_t; b < patch.count_t; ++b) {
    if (patch.knots_t[b] == patch.knots_t[b + 1]) continue;  // an empty span holds no point
    for (int a = patch.degree_s; a < patch.count_s; ++a) {
      if (patch.knots_s[a] == patch.knots_s[a + 1]) continue;
      bound = std::max(bound, span_bound_s(patch, a, b));
    }
  }
  return bound;
}

}  // namespace

DerivativeBound derivative_bound(const Patch& patch) {
  return {bound_s(patch), bound_s(transposed(patch))};
}

DerivativeBound derivative_bound(const Patch& patch, const glm::dmat3& transform) {
  Patch mapped = patch;
  for (glm::dvec3& point : mapped.points) point = transform * point;
  return derivative_bound(mapped);
}

}  // namespace tmu::host::nurbs
