// Rational B-spline (NURBS) patches in double precision on the host: validity, evaluation of the
// point and its first partial derivatives, the unit normal, and upper bounds of the derivatives
// over the whole patch. The bounds are what 004's claims 8-10 divide by a screen-space step to
// get the tessellation step counts n_s = ||S'_s|| / d_s,mc and n_t = ||S'_t|| / d_t,mc.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tmu::host::nurbs {

// A rational B-spline patch (tensor product), in modelling coordinates.
struct Patch {
  int degree_s = 1, degree_t = 1;        // 1..3
  int count_s = 2, count_t = 2;          // control points along s and along t
  std::vector<double> knots_s, knots_t;  // count + degree + 1 each, non-decreasing
  std::vector<glm::dvec3> points;        // count_s * count_t, index i + count_s * j (i along s)
  std::vector<double> weights;           // same size and index, each > 0

  const glm::dvec3& point(int i, int j) const { return points[i + count_s * j]; }
  double weight(int i, int j) const { return weights[i + count_s * j]; }

  // The parameter domain: [knots_s[degree_s], knots_s[count_s]] x
  // [knots_t[degree_t], knots_t[count_t]]. Knot vectors need not be clamped: outside the domain
  // the basis functions do not sum to one.
  double s_min() const { return knots_s[degree_s]; }
  double s_max() const { return knots_s[count_s]; }
  double t_min() const { return knots_t[degree_t]; }
  double t_max() const { return knots_t[count_t]; }
};

// Why a patch is not valid, or "" when it is: names the field and the reason, e.g.
// "knots_s: not non-decreasing at index 3 (2 after 2.5)",
// "points: 12 control points, expected count_s * count_t = 15", "weights[4]: 0 must be > 0",
// "degree_s: 4 is out of range 1..3", "knots_s: 6 knots, expected count_s + degree_s + 1 = 7",
// "knots_s: empty parameter domain (knots_s[2] = knots_s[3] = 1)",
// "count_t: 2 control points, expected at least degree_t + 1 = 3",
// "knots_t[1]: nan is not finite", "points[7]: (0, inf, 1) is not finite".
// The functions below expect a valid patch.
std::string invalid_reason(const Patch& patch);

struct SurfacePoint {
  glm::dvec3 position{0}, d_ds{0}, d_dt{0};  // S(s,t), dS/ds, dS/dt
};

// Point and first partial derivatives by Cox-de Boor (The NURBS Book A2.2, A2.3) on the
// homogeneous sums A = sum N_i M_j w_ij P_ij, W = sum N_i M_j w_ij: S = A / W and
// dS/ds = (A_s - S W_s) / W (the quotient rule), likewise in t. s and t are clamped into the
// domain; a parameter on a knot takes the span that starts there (the derivative from above at a
// C0 joint), except at the domain's upper end, which takes the last non-empty span.
SurfacePoint evaluate(const Patch& patch, double s, double t);

// The unit normal (dS/ds x dS/dt) / ||dS/ds x dS/dt||. Where the cross product vanishes (a
// collapsed pole, where dS/ds = 0; a zero derivative) it is the limit from inside: the normal
// at (s, t) each moved toward the domain's centre by 1e-7 of the domain's extent. That moves the
// point by about 1e-7 of the patch, so the normal is off its limit by an angle of that order;
// the surface is not evaluated outside its domain. "Vanishes" is relative:
// ||n|| <= 1e-10 (||dS/ds|| + ||dS/dt||)^2 (rounding leaves ~1e-16 at a collapsed pole, and a
// normal with sin(angle) below that is not defined by the surface anyway). Returns (0, 0, 0)
// when the moved point is degenerate too (a patch collapsed to a curve or a point).
glm::dvec3 unit_normal(const Patch& patch, double s, double t);

// Upper bounds of ||dS/ds|| and ||dS/dt|| over the whole domain, from the control net alone
// (no sampling), valid for rational patches.
//
// Derivation, in s (t likewise, with the roles swapped). Let p = degree_s, u = knots_s, N_i the
// degree-p basis in s, M_j the degree-q basis in t. With A = sum N_i M_j w_ij P_ij,
// W = sum N_i M_j w_ij and S = A / W:
//   dS/ds = (A_s - S W_s) / W,   A_s - S W_s = sum_j M_j sum_i N'_i w_ij (P_ij - S).
// With c_ij = w_ij (P_ij - S) and N'_i = p N_{i,p-1} / (u_{i+p} - u_i)
//                                       - p N_{i+1,p-1} / (u_{i+p+1} - u_{i+1}):
//   sum_i N'_i c_ij = sum_i N_{i+1,p-1} p (c_{i+1,j} - c_ij) / (u_{i+p+1} - u_{i+1}),
// the end terms N_{0,p-1} and N_{count_s,p-1} being zero inside the domain. On one span
// [u_a, u_a+1) x [v_b, v_b+1) only the local net i in a-p..a, j in b-q..b takes part: the nonzero
// N_{i+1,p-1} have i in a-p..a-1 and sum to 1 there (the knot difference is >= u_a+1 - u_a > 0
// for these i), and the nonzero M_j sum to 1. Writing the difference both ways,
//   c_{i+1,j} - c_ij = w_ij (P_{i+1,j} - P_ij) + (w_{i+1,j} - w_ij) (P_{i+1,j} - S)
//                    = w_{i+1,j} (P_{i+1,j} - P_ij) + (w_{i+1,j} - w_ij) (P_ij - S),
// and S lies in the convex hull of the local net (W > 0, nonnegative basis), so ||P - S|| <=
// R(P), the largest distance from P to a local control point (a convex function is largest at a
// vertex of the hull). So ||A_s - S W_s|| <= sum_j M_j X_j with
//   X_j = max over local i of p min(w_ij |dP| + |dw| R(P_{i+1,j}), w_{i+1,j} |dP| + |dw| R(P_ij))
//         / (u_{i+p+1} - u_{i+1}),       dP = P_{i+1,j} - P_ij, dw = w_{i+1,j} - w_ij.
// The denominator W = sum_j M_j sum_i N_i w_ij >= sum_j M_j m_j, m_j the smallest local weight of
// row j (the N_i sum to 1), and sum_j M_j X_j / sum_j M_j m_j <= max_j X_j / m_j (a mediant of
// nonnegative terms). So on that span ||dS/ds|| <= max over local rows j of X_j / m_j, and the
// bound is the largest over the non-empty spans. With equal weights it is the classical
// hodograph bound max p |dP| / (u_{i+p+1} - u_{i+1}); it is never larger than the global form
// p (w_{i+1,j} |dP| + |dw| D) / ((u_{i+p+1} - u_{i+1}) w_min) with D the net's diameter and w_min
// over the whole net. It bounds the one-sided derivatives at C0 joints too.
struct DerivativeBound {
  double s = 0, t = 0;
};
DerivativeBound derivative_bound(const Patch& patch);

// The bound of the patch under a linear map M applied to its points (the modelling transform,
// without translation, which does not change derivatives): the bound of the net M * P.
DerivativeBound derivative_bound(const Patch& patch, const glm::dmat3& transform);

}  // namespace tmu::host::nurbs
