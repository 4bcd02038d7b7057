// evaluate() and unit_normal(): the B-spline basis and its first derivative on one span (The NURBS
// Book A2.1-A2.3), summed over the local net in homogeneous form, then the quotient rule.
#include <algorithm>
#include <array>
#include <cmath>

#include "nurbs/patch.hpp"

namespace tmu::host::nurbs {
namespace {

// The span a (degree <= a < count) with knots[a] <= u < knots[a + 1]: the span that starts at u
// when u is a knot, except at the domain's upper end, which takes the last non-empty span.
int find_span(const std::vector<double>& knots, int degree, int count, double u) {
  const auto first = knots.begin() + degree, last = knots.begin() + count + 1;
  int a = static_cast<int>(std::upper_bound(first, last, u) - knots.begin()) - 1;
  a = std::clamp(a, degree, count - 1);
  while (knots[a] == knots[a + 1]) --a;  // only at the upper end; the domain is not empty
  return a;
}

// The degree + 1 basis functions N_{a-degree..a} that are nonzero on span a, at u, and their
// first derivatives.
struct Basis {
  std::array<double, 4> value{}, derivative{};
};

Basis basis(const std::vector<double>& knots, int degree, int a, double u) {
  // Cox-de Boor's triangle (A2.2), keeping the degree - 1 row for the derivatives.
  std::array<double, 4> n{1, 0, 0, 0}, lower{}, left{}, right{};
  for (int k = 1; k <= degree; ++k) {
    if (k == degree) lower = n;  // N_{a-degree+1..a, degree-1}
    left[k] = u - knots[a + 1 - k];
    right[k] = knots[a + k] - u;
    double saved = 0;
    for (int r = 0; r < k; ++r) {
      const double temp = n[r] / (right[r + 1] + left[k - r]);  // a knot span >= u_a+1 - u_a > 0
      n[r] = saved + right[r + 1] * temp;
      saved = left[k - r] * temp;
    }
    n[k] = saved;
  }
  // N'_{i,p} = p N_{i,p-1} / (u_{i+p} - u_i) - p N_{i+1,p-1} / (u_{i+p+1} - u_{i+1}) with
  // i = a - degree + r; lower[r - 1] is N_{i,p-1} and lower[r] is N_{i+1,p-1}. A nonzero lower
  // function's support contains the span, so its denominator is positive.
  Basis b;
  b.value = n;
  for (int r = 0; r <= degree; ++r) {
    double d = 0;
    if (r >= 1) d += lower[r - 1] / (knots[a + r] - knots[a - degree + r]);
    if (r < degree) d -= lower[r] / (knots[a + r + 1] - knots[a - degree + r + 1]);
    b.derivative[r] = degree * d;
  }
  return b;
}

}  // namespace

SurfacePoint evaluate(const Patch& patch, double s, double t) {
  s = std::clamp(s, patch.s_min(), patch.s_max());
  t = std::clamp(t, patch.t_min(), patch.t_max());
  const int p = patch.degree_s, q = patch.degree_t;
  const int a = find_span(patch.knots_s, p, patch.count_s, s);
  const int b = find_span(patch.knots_t, q, patch.count_t, t);
  const Basis bs = basis(patch.knots_s, p, a, s);
  const Basis bt = basis(patch.knots_t, q, b, t);

  // Homogeneous sums: A = sum N M w P, W = sum N M w, and their s and t derivatives.
  glm::dvec3 sum{0}, sum_s{0}, sum_t{0};
  double w = 0, w_s = 0, w_t = 0;
  for (int l = 0; l <= q; ++l) {
    for (int k = 0; k <= p; ++k) {
      const int i = a - p + k, j = b - q + l;
      const double wp = patch.weight(i, j);
      const glm::dvec3 pw = wp * patch.point(i, j);
      const double n = bs.value[k] * bt.value[l];
      const double n_s = bs.derivative[k] * bt.value[l];
      const double n_t = bs.value[k] * bt.derivative[l];
      sum += n * pw;
      sum_s += n_s * pw;
      sum_t += n_t * pw;
      w += n * wp;
      w_s += n_s * wp;
      w_t += n_t * wp;
    }
  }
  SurfacePoint out;
  out.position = sum / w;
  out.d_ds = (sum_s - out.position * w_s) / w;
  out.d_dt = (sum_t - out.position * w_t) / w;
  return out;
}

namespace {

// The cross product is "vanishing" when it is below 1e-10 of the derivatives' scale squared.
bool vanishes(const SurfacePoint& e, const glm::dvec3& n) {
  const double scale = glm::length(e.d_ds) + glm::length(e.d_dt);
  return glm::length(n) <= 1e-10 * scale * scale;
}

// u moved toward the centre of [lo, hi] by `fraction` of its extent (not moved at the centre).
double toward_centre(double u, double lo, double hi, double fraction) {
  const double centre = (lo + hi) / 2, step = fraction * (hi - lo);
  if (u < centre) return std::min(u + step, centre);
  if (u > centre) return std::max(u - step, centre);
  return u;
}

}  // namespace

glm::dvec3 unit_normal(const Patch& patch, double s, double t) {
  s = std::clamp(s, patch.s_min(), patch.s_max());
  t = std::clamp(t, patch.t_min(), patch.t_max());
  SurfacePoint e = evaluate(patch, s, t);
  glm::dvec3 n = glm::cross(e.d_ds, e.d_dt);
  if (vanishes(e, n)) {
    constexpr double kFraction = 1e-7;
    e = evaluate(patch, toward_centre(s, patch.s_min(), patch.s_max(), kFraction),
                 toward_centre(t, patch.t_min(), patch.t_max(), kFraction));
    n = glm::cross(e.d_ds, e.d_dt);
    if (vanishes(e, n)) return glm::dvec3(0);
  }
  return n / glm::length(n);
}

}  // namespace tmu::host::nurbs
