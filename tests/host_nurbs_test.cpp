// NURBS patches (004 claims 8-10): evaluation against Open CASCADE's Geom_BSplineSurface (the
// independent reference, used only here), the derivative bounds against dense samples, the exact
// quadric nets against the analytic shapes, and the hard cases (collapsed poles, C0 joints,
// weights six decades apart, bilinear patches, every invalid_reason).
#include <gtest/gtest.h>

#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <iostream>
#include <random>

#include "nurbs/conics.hpp"
#include "nurbs/patch.hpp"

namespace tmu::host::nurbs {
namespace {

// ---- Random patches ------------------------------------------------------------------------

// A flat knot vector of count + degree + 1 knots: each end's multiplicity degree + 1 (clamped)
// half the time, else 1..degree + 1 (mostly unclamped); interior ones 1..degree (degree = a C0
// joint); distinct values 0.05..1 apart from a random start. OCCT takes all of these (its
// non-periodic surfaces allow end multiplicities up to degree + 1, interior up to degree).
std::vector<double> random_knots(std::mt19937_64& rng, int degree, int count) {
  const int total = count + degree + 1;
  std::uniform_int_distribution<int> any_mult(1, degree + 1), inner_mult(1, degree);
  std::uniform_real_distribution<double> gap(0.05, 1.0), start(-2.0, 2.0);
  auto end_mult = [&] { return rng() % 2 ? degree + 1 : any_mult(rng); };
  std::vector<int> mults{end_mult()};
  const int last = end_mult();
  int remaining = total - mults[0] - last;  // >= 0: count >= degree + 1
  while (remaining > 0) {
    // Half the interior knots simple, half of any multiplicity up to the degree.
    const int m = std::min(remaining, rng() % 2 ? 1 : inner_mult(rng));
    mults.push_back(m);
    remaining -= m;
  }
  mults.push_back(last);
  std::vector<double> knots;
  double value = start(rng);
  for (int m : mults) {
    knots.insert(knots.end(), m, value);
    value += gap(rng);
  }
  return knots;
}

// Degrees 1..3, counts degree + 1..8, points in [-1, 1]^3, weights log-uniform in [1e-3, 1e3];
// redrawn until valid (a short knot vector can have an empty domain).
Patch random_patch(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> degree(1, 3);
  std::uniform_real_distribution<double> coordinate(-1, 1), log_weight(-3, 3);
  while (true) {
    Patch patch;
    patch.degree_s = degree(rng);
    patch.degree_t = degree(rng);
    patch.count_s = std::uniform_int_distribution<int>(patch.degree_s + 1, 8)(rng);
    patch.count_t = std::uniform_int_distribution<int>(patch.degree_t + 1, 8)(rng);
    patch.knots_s = random_knots(rng, patch.degree_s, patch.count_s);
    patch.knots_t = random_knots(rng, patch.degree_t, patch.count_t);
    for (int k = 0; k < patch.count_s * patch.count_t; ++k) {
      patch.points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
      patch.weights.push_back(std::pow(10.0, log_weight(rng)));
    }
    if (invalid_reason(patch).empty()) return patch;
  }
}

bool clamped(const std::vector<double>& knots, int degree) {
  return knots[0] == knots[degree] && knots[knots.size() - 1] == knots[knots.size() - 1 - degree];
}

// The net's size: its bounding box's diagonal.
double net_size(const Patch& patch) {
  glm::dvec3 lo = patch.points[0], hi = patch.points[0];
  for (const glm::dvec3& p : patch.points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

// Parameters to sample in [lo, hi]: the ends, every knot inside, and `random` more.
std::vector<double> samples(std::mt19937_64& rng, const std::vector<double>& knots, double lo,
                            double hi, int random) {
  std::vector<double> out{lo, hi};
  for (double k : knots) {
    if (k > lo && k < hi) out.push_back(k);
  }
  std::uniform_real_distribution<double> u(lo, hi);
  for (int k = 0; k < random; ++k) out.push_back(u(rng));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// ---- The reference: OCCT ------------------------------------------------------------------

// Distinct knots and their multiplicities, as OCCT takes them.
void to_occt_knots(const std::vector<double>& flat, TColStd_Array1OfReal& knots,
                   TColStd_Array1OfInteger& mults) {
  std::vector<double> values;
  std::vector<int> counts;
  for (double k : flat) {
    if (!values.empty() && values.back() == k) {
      ++counts.back();
    } else {
      values.push_back(k);
      counts.push_back(1);
    }
  }
  knots.Resize(1, static_cast<int>(values.size()), false);
  mults.Resize(1, static_cast<int>(values.size()), false);
  for (std::size_t k = 0; k < values.size(); ++k) {
    knots(static_cast<int>(k) + 1) = values[k];
    mults(static_cast<int>(k) + 1) = counts[k];
  }
}

// OCCT's surface of the patch: poles(i + 1, j + 1), its U being our s.
Handle(Geom_BSplineSurface) to_occt(const Patch& patch) {
  TColgp_Array2OfPnt poles(1, patch.count_s, 1, patch.count_t);
  TColStd_Array2OfReal weights(1, patch.count_s, 1, patch.count_t);
  for (int j = 0; j < patch.count_t; ++j) {
    for (int i = 0; i < patch.count_s; ++i) {
      const glm::dvec3& p = patch.point(i, j);
      poles(i + 1, j + 1) = gp_Pnt(p.x, p.y, p.z);
      weights(i + 1, j + 1) = patch.weight(i, j);
    }
  }
  TColStd_Array1OfReal knots_s(1, 1), knots_t(1, 1);
  TColStd_Array1OfInteger mults_s(1, 1), mults_t(1, 1);
  to_occt_knots(patch.knots_s, knots_s, mults_s);
  to_occt_knots(patch.knots_t, knots_t, mults_t);
  return new Geom_BSplineSurface(poles, weights, knots_s, knots_t, mults_s, mults_t, patch.degree_s,
                                 patch.degree_t);
}

glm::dvec3 to_glm(const gp_XYZ& v) { return {v.X(), v.Y(), v.Z()}; }

// Whether u is a knot of multiplicity >= degree strictly inside the domain: a C0 joint, where
// the two sides' derivatives differ and OCCT may take the other side.
bool at_c0_joint(const std::vector<double>& knots, int degree, double lo, double hi, double u) {
  if (u <= lo || u >= hi) return false;
  return std::count(knots.begin(), knots.end(), u) >= degree;
}

// ---- 1. Random patches against OCCT ------------------------------------------------------------

// Bounds: positions within 1e-9 of the net's size; each derivative within 1e-9 of its bound
// (derivative_bound: the derivative's natural scale, including the weight ratios a rational
// quotient's rounding is amplified by). Both are ~1e4 x what double rounding leaves (the sums
// have at most 16 terms of magnitude <= the net's size times w_max / w_min <= 1e6 before the
// division, hence relative errors up to ~1e6 eps ~ 2e-10 of the terms); measured figures are
// printed. Derivatives at a C0 joint are one-sided and are compared only when OCCT took the
// same side (otherwise against the other side, evaluated just below the knot).
TEST(HostNurbsTest, MatchesOcctOnRandomPatches) {
  const uint64_t seed = 20240604;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  double worst_position = 0, worst_derivative = 0;
  int patches = 0, unclamped = 0, with_joint = 0, points = 0;
  for (int n = 0; n < 300; ++n) {
    const Patch patch = random_patch(rng);
    SCOPED_TRACE(::testing::Message()
                 << "patch " << n << " degrees " << patch.degree_s << "," << patch.degree_t
                 << " counts " << patch.count_s << "," << patch.count_t);
    Handle(Geom_BSplineSurface) reference;
    try {
      reference = to_occt(patch);
    } catch (const Standard_Failure& e) {
      FAIL() << "OCCT rejected the patch: " << e.GetMessageString();
    }
    double u1, u2, v1, v2;
    reference->Bounds(u1, u2, v1, v2);
    EXPECT_EQ(u1, patch.s_min());
    EXPECT_EQ(u2, patch.s_max());
    EXPECT_EQ(v1, patch.t_min());
    EXPECT_EQ(v2, patch.t_max());
    ++patches;
    unclamped += !clamped(patch.knots_s, patch.degree_s) || !clamped(patch.knots_t, patch.degree_t);
    const double size = net_size(patch);
    const DerivativeBound bound = derivative_bound(patch);
    bool joint = false;
    for (double s : samples(rng, patch.knots_s, patch.s_min(), patch.s_max(), 12)) {
      for (double t : samples(rng, patch.knots_t, patch.t_min(), patch.t_max(), 12)) {
        const SurfacePoint e = evaluate(patch, s, t);
        gp_Pnt p;
        gp_Vec du, dv;
        reference->D1(s, t, p, du, dv);
        const double position = glm::length(e.position - to_glm(p.XYZ())) / size;
        EXPECT_LE(position, 1e-9) << "s " << s << " t " << t;
        worst_position = std::max(worst_position, position);
        // At a C0 joint, the side OCCT did not take: our derivative just below the knot.
        const bool joint_s =
            at_c0_joint(patch.knots_s, patch.degree_s, patch.s_min(), patch.s_max(), s);
        const bool joint_t =
            at_c0_joint(patch.knots_t, patch.degree_t, patch.t_min(), patch.t_max(), t);
        joint = joint || joint_s || joint_t;
        auto error = [&](const glm::dvec3& ours, const gp_Vec& theirs, double scale) {
          return glm::length(ours - to_glm(theirs.XYZ())) / scale;
        };
        double error_s = error(e.d_ds, du, bound.s), error_t = error(e.d_dt, dv, bound.t);
        if (joint_s || joint_t) {
          const SurfacePoint below = evaluate(patch, joint_s ? std::nextafter(s, -INFINITY) : s,
                                              joint_t ? std::nextafter(t, -INFINITY) : t);
          error_s = std::min(error_s, error(below.d_ds, du, bound.s));
          error_t = std::min(error_t, error(below.d_dt, dv, bound.t));
        }
        EXPECT_LE(error_s, 1e-9) << "dS/ds at s " << s << " t " << t;
        EXPECT_LE(error_t, 1e-9) << "dS/dt at s " << s << " t " << t;
        worst_derivative = std::max({worst_derivative, error_s, error_t});
        // The bound holds at every sample (it is exact arithmetic's bound; 1e-12 for rounding).
        EXPECT_GE(bound.s, glm::length(e.d_ds) * (1 - 1e-12)) << "s " << s << " t " << t;
        EXPECT_GE(bound.t, glm::length(e.d_dt) * (1 - 1e-12)) << "s " << s << " t " << t;
        ++points;
      }
    }
    with_joint += joint;
  }
  std::cout << patches << " patches (" << unclamped << " with an unclamped knot vector, "
            << with_joint << " with a C0 joint), " << points << " points: worst position error "
            << worst_position << " of the net's size, worst derivative error " << worst_derivative
            << " of the derivative bound\n";
}

// ---- 2. Derivative bounds -----------------------------------------------------------------------

// The global form of the bound (the brief's: w_min and the diameter D over the whole net, D the
// bounding box's diagonal), in s; patch.hpp's per-span bound is never larger.
double global_bound_s(const Patch& patch) {
  const double w_min = *std::min_element(patch.weights.begin(), patch.weights.end());
  const double d = net_size(patch);
  const int p = patch.degree_s;
  double bound = 0;
  for (int j = 0; j < patch.count_t; ++j) {
    for (int i = 0; i + 1 < patch.count_s; ++i) {
      const double du = patch.knots_s[i + p + 1] - patch.knots_s[i + 1];
      if (du == 0) continue;  // N_{i+1,p-1} is identically zero
      const double w0 = patch.weight(i, j), w1 = patch.weight(i + 1, j);
      const double dp = glm::length(patch.point(i + 1, j) - patch.point(i, j));
      bound = std::max(bound, p * (w1 * dp + std::abs(w1 - w0) * d) / (du * w_min));
    }
  }
  return bound;
}

// The patch with s and t exchanged, to reuse global_bound_s in t.
Patch transposed(const Patch& patch) {
  Patch out = patch;
  std::swap(out.degree_s, out.degree_t);
  std::swap(out.count_s, out.count_t);
  std::swap(out.knots_s, out.knots_t);
  for (int j = 0; j < patch.count_t; ++j) {
    for (int i = 0; i < patch.count_s; ++i) {
      out.points[j + out.count_s * i] = patch.point(i, j);
      out.weights[j + out.count_s * i] = patch.weight(i, j);
    }
  }
  return out;
}

// The largest ||M dS/ds|| and ||M dS/dt|| on a grid of n x n parameters plus every knot.
DerivativeBound sampled_maximum(const Patch& patch, int n, const glm::dmat3& m = glm::dmat3(1)) {
  auto grid = [n](const std::vector<double>& knots, double lo, double hi) {
    std::vector<double> out(knots.begin(), knots.end());
    for (int k = 0; k <= n; ++k) out.push_back(lo + (hi - lo) * k / n);
    std::erase_if(out, [&](double u) { return u < lo || u > hi; });
    return out;
  };
  DerivativeBound largest;
  for (double s : grid(patch.knots_s, patch.s_min(), patch.s_max())) {
    for (double t : grid(patch.knots_t, patch.t_min(), patch.t_max())) {
      const SurfacePoint e = evaluate(patch, s, t);
      largest.s = std::max(largest.s, glm::length(m * e.d_ds));
      largest.t = std::max(largest.t, glm::length(m * e.d_dt));
      // Just below a knot: the other side of a joint.
      const SurfacePoint below_s = evaluate(patch, std::nextafter(s, -1e300), t);
      const SurfacePoint below_t = evaluate(patch, s, std::nextafter(t, -1e300));
      largest.s = std::max(largest.s, glm::length(m * below_s.d_ds));
      largest.t = std::max(largest.t, glm::length(m * below_t.d_dt));
    }
  }
  return largest;
}

// The bound holds in exact arithmetic; 1e-12 allows for the rounding of both sides.
void expect_bound_holds(const DerivativeBound& bound, const DerivativeBound& sampled) {
  EXPECT_GE(bound.s, sampled.s * (1 - 1e-12));
  EXPECT_GE(bound.t, sampled.t * (1 - 1e-12));
}

// A shear, a rotation and an uneven scale: the modelling transform's linear part.
glm::dmat3 some_transform() {
  const double c = std::cos(0.7), s = std::sin(0.7);
  const glm::dmat3 rotation(c, 0, -s, 0, 1, 0, s, 0, c);  // columns
  const glm::dmat3 shear(1, 0.3, 0, 0, 1, 0, -0.4, 0, 1);
  const glm::dmat3 scale(2.5, 0, 0, 0, 0.2, 0, 0, 0, 1.3);
  return rotation * shear * scale;
}

TEST(HostNurbsTest, DerivativeBoundHoldsOnRandomPatches) {
  const uint64_t seed = 20240605;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  double tightest = 1e300, loosest = 0;
  for (int n = 0; n < 100; ++n) {
    const Patch patch = random_patch(rng);
    SCOPED_TRACE(::testing::Message() << "patch " << n);
    const DerivativeBound bound = derivative_bound(patch);
    const DerivativeBound sampled = sampled_maximum(patch, 60);
    expect_bound_holds(bound, sampled);
    expect_bound_holds(derivative_bound(patch, some_transform()),
                       sampled_maximum(patch, 60, some_transform()));
    // Never larger than the global form (R(P) <= D, local w_min >= global w_min).
    EXPECT_LE(bound.s, global_bound_s(patch) * (1 + 1e-12));
    EXPECT_LE(bound.t, global_bound_s(transposed(patch)) * (1 + 1e-12));
    for (double ratio : {bound.s / sampled.s, bound.t / sampled.t}) {
      tightest = std::min(tightest, ratio);
      loosest = std::max(loosest, ratio);
    }
  }
  std::cout << "bound / sampled maximum on random patches (weights 1e-3..1e3): " << tightest
            << " .. " << loosest << "\n";
}

// ---- 2. The quadrics ----------------------------------------------------------------------------

// Calls check(s, t, evaluated point, unit normal) on a (n + 1) x (n + 1) grid over [0,1]^2 (which
// holds every knot of the quadrics for n a multiple of 4).
template <typename Check>
void for_grid(const Patch& patch, int n, Check check) {
  for (int a = 0; a <= n; ++a) {
    for (int b = 0; b <= n; ++b) {
      const double s = double(a) / n, t = double(b) / n;
      check(s, t, evaluate(patch, s, t), unit_normal(patch, s, t));
    }
  }
}

// Prints how tight the bound is on a quadric (and the global form's), and checks that it holds,
// also under a modelling transform.
void report_tightness(const char* name, const Patch& patch) {
  ASSERT_EQ(invalid_reason(patch), "");
  const DerivativeBound bound = derivative_bound(patch), sampled = sampled_maximum(patch, 400);
  expect_bound_holds(bound, sampled);
  expect_bound_holds(derivative_bound(patch, some_transform()),
                     sampled_maximum(patch, 400, some_transform()));
  std::cout << name << ": bound / sampled maximum: s " << bound.s / sampled.s << ", t "
            << bound.t / sampled.t << " (global form: s " << global_bound_s(patch) / sampled.s
            << ", t " << global_bound_s(transposed(patch)) / sampled.t << ")\n";
}

// Every point at distance r from the centre, to 1e-12 of r (the rational sums round to a few
// ulps); the normal is the outward radius, to 1e-9 (1e-6 at the poles, where it is the limit
// taken 1e-7 of the domain inside: an angle of ~3e-7).
TEST(HostNurbsTest, SphereIsExact) {
  const double r = 2.5;
  const Patch patch = sphere(r);
  for_grid(patch, 200, [&](double s, double t, const SurfacePoint& e, const glm::dvec3& n) {
    SCOPED_TRACE(::testing::Message() << "s " << s << " t " << t);
    EXPECT_NEAR(glm::length(e.position), r, 1e-12 * r);
    const bool pole = t == 0 || t == 1;
    EXPECT_NEAR(glm::length(n - e.position / r), 0, pole ? 1e-6 : 1e-9);
  });
  EXPECT_NEAR(glm::length(evaluate(patch, 0.3, 0).position - glm::dvec3(0, r, 0)), 0, 1e-15);
  EXPECT_NEAR(glm::length(evaluate(patch, 0, 0.5).position - glm::dvec3(r, 0, 0)), 0, 1e-15);
  report_tightness("sphere", patch);
}

// Every point at distance `minor` from the tube's centre circle, to 1e-12 of the torus's size.
TEST(HostNurbsTest, TorusIsExact) {
  const double major = 3, minor = 0.8;
  const Patch patch = torus(major, minor);
  for_grid(patch, 200, [&](double s, double t, const SurfacePoint& e, const glm::dvec3& n) {
    SCOPED_TRACE(::testing::Message() << "s " << s << " t " << t);
    const glm::dvec3 p = e.position;
    const glm::dvec3 centre = major * glm::normalize(glm::dvec3(p.x, 0, p.z));
    EXPECT_NEAR(glm::length(p - centre), minor, 1e-12 * (major + minor));
    EXPECT_NEAR(glm::length(n - (p - centre) / minor), 0, 1e-9);
  });
  EXPECT_NEAR(glm::length(evaluate(patch, 0, 0).position - glm::dvec3(major + minor, 0, 0)), 0,
              1e-15);
  report_tightness("torus", patch);
}

// Every point at distance `radius` from the Y axis and y = height (1/2 - t): within the height.
TEST(HostNurbsTest, CylinderIsExact) {
  const double radius = 1.5, height = 4;
  const Patch patch = cylinder(radius, height);
  for_grid(patch, 200, [&](double s, double t, const SurfacePoint& e, const glm::dvec3& n) {
    SCOPED_TRACE(::testing::Message() << "s " << s << " t " << t);
    const glm::dvec3 p = e.position;
    EXPECT_NEAR(std::hypot(p.x, p.z), radius, 1e-12 * radius);
    EXPECT_NEAR(p.y, height * (0.5 - t), 1e-12 * height);
    EXPECT_NEAR(glm::length(n - glm::dvec3(p.x, 0, p.z) / radius), 0, 1e-9);
  });
  report_tightness("cylinder", patch);
}

// ---- 3. Hard cases ------------------------------------------------------------------------------

// At the poles the whole row of points is one point: dS/ds = 0 (to rounding), dS/dt is not,
// and unit_normal takes the limit: (0, 1, 0) at the north pole, (0, -1, 0) at the south.
TEST(HostNurbsTest, SpherePolesCollapse) {
  const double r = 2;
  const Patch patch = sphere(r);
  for (double s : {0.0, 0.1, 0.25, 0.6, 1.0}) {
    SCOPED_TRACE(::testing::Message() << "s " << s);
    for (double t : {0.0, 1.0}) {
      const SurfacePoint e = evaluate(patch, s, t);
      EXPECT_LE(glm::length(e.d_ds), 1e-12 * r);
      EXPECT_GT(glm::length(e.d_dt), r);  // 2 (sqrt(2)/2) r / (1/2) = 2.83 r
      const glm::dvec3 pole(0, t == 0 ? 1 : -1, 0);
      EXPECT_NEAR(glm::length(e.position - r * pole), 0, 1e-15);
      EXPECT_NEAR(glm::length(unit_normal(patch, s, t) - pole), 0, 1e-6);
    }
  }
}

// A C0 joint (interior knot of multiplicity = degree): the surface is continuous across it, the
// point there is the joint's control point, and the two one-sided derivatives are the two
// control legs p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1}) (equal weights).
TEST(HostNurbsTest, C0JointIsContinuous) {
  Patch patch;
  patch.degree_s = 2;
  patch.count_s = 5;
  patch.knots_s = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
  patch.knots_t = {0, 0, 1, 1};
  patch.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0},
                  {0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {2, 2, 1}};
  patch.weights.assign(10, 1.0);
  ASSERT_EQ(invalid_reason(patch), "");
  const SurfacePoint above = evaluate(patch, 0.5, 0);
  const SurfacePoint below = evaluate(patch, std::nextafter(0.5, 0.0), 0);
  EXPECT_NEAR(glm::length(above.position - glm::dvec3(2, 0, 0)), 0, 1e-15);
  EXPECT_NEAR(glm::length(below.position - glm::dvec3(2, 0, 0)), 0, 1e-15);
  EXPECT_NEAR(glm::length(below.d_ds - glm::dvec3(4, 0, 0)), 0, 1e-12);  // 2 (P2 - P1) / 0.5
  EXPECT_NEAR(glm::length(above.d_ds - glm::dvec3(0, 4, 0)), 0, 1e-12);  // 2 (P3 - P2) / 0.5

  // Rational: continuity across the joint at the scale of the bound (|S(a) - S(b)| <= bound |a -
  // b|).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> log_weight(-3, 3);
  for (double& w : patch.weights) w = std::pow(10.0, log_weight(rng));
  const double bound = derivative_bound(patch).s;
  for (double step : {1e-3, 1e-6, 1e-9}) {
    for (double t : {0.0, 0.4, 1.0}) {
      const double gap = glm::length(evaluate(patch, 0.5 + step, t).position -
                                     evaluate(patch, 0.5 - step, t).position);
      EXPECT_LE(gap, bound * 2 * step * (1 + 1e-9) + 1e-15) << "step " << step << " t " << t;
    }
  }
}

// Weights 1e-3 and 1e3 in one net (a checkerboard): against OCCT on a dense grid, every point in
// the net's bounding box (the convex hull property), the bound holds.
TEST(HostNurbsTest, ExtremeWeightsInOneNet) {
  Patch patch;
  patch.degree_s = 3;
  patch.degree_t = 2;
  patch.count_s = 5;
  patch.count_t = 4;
  patch.knots_s = {0, 0, 0, 0, 0.4, 1, 1, 1, 1};
  patch.knots_t = {0, 0, 0, 0.5, 1, 1, 1};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int j = 0; j < patch.count_t; ++j) {
    for (int i = 0; i < patch.count_s; ++i) {
      patch.points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
      patch.weights.push_back((i + j) % 2 ? 1e3 : 1e-3);
    }
  }
  ASSERT_EQ(invalid_reason(patch), "");
  const Handle(Geom_BSplineSurface) reference = to_occt(patch);
  const DerivativeBound bound = derivative_bound(patch);
  glm::dvec3 lo = patch.points[0], hi = patch.points[0];
  for (const glm::dvec3& p : patch.points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double size = net_size(patch);
  for_grid(patch, 100, [&](double s, double t, const SurfacePoint& e, const glm::dvec3&) {
    SCOPED_TRACE(::testing::Message() << "s " << s << " t " << t);
    gp_Pnt p;
    gp_Vec du, dv;
    reference->D1(s, t, p, du, dv);
    EXPECT_LE(glm::length(e.position - to_glm(p.XYZ())), 1e-9 * size);
    EXPECT_LE(glm::length(e.d_ds - to_glm(du.XYZ())), 1e-9 * bound.s);
    EXPECT_LE(glm::length(e.d_dt - to_glm(dv.XYZ())), 1e-9 * bound.t);
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(e.position, lo - 1e-12 * size)));
    EXPECT_TRUE(glm::all(glm::lessThanEqual(e.position, hi + 1e-12 * size)));
  });
  expect_bound_holds(bound, sampled_maximum(patch, 200));
}

// Degree 1 x 1 with equal weights is bilinear interpolation of the corners, on any knots; its
// bound is the classical one, max edge / knot span, reached at a corner.
TEST(HostNurbsTest, BilinearPatchInterpolatesCorners) {
  Patch patch;
  patch.knots_s = {-1, -1, 3, 3};
  patch.knots_t = {0, 0, 0.5, 0.5};
  const glm::dvec3 p00(0, 0, 0), p10(2, 0.5, 0), p01(0.3, 1, 1), p11(2, 2, -1);
  patch.points = {p00, p10, p01, p11};
  patch.weights.assign(4, 2.0);
  ASSERT_EQ(invalid_reason(patch), "");
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 200; ++k) {
    const double u = k == 0 ? 0 : k == 1 ? 1 : unit(rng), v = k == 1 ? 1 : unit(rng);
    const SurfacePoint e = evaluate(patch, -1 + 4 * u, 0.5 * v);
    const glm::dvec3 expected =
        (1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + (1 - u) * v * p01 + u * v * p11;
    EXPECT_NEAR(glm::length(e.position - expected), 0, 1e-14);
    EXPECT_NEAR(glm::length(e.d_ds - ((1 - v) * (p10 - p00) + v * (p11 - p01)) / 4.0), 0, 1e-14);
    EXPECT_NEAR(glm::length(e.d_dt - ((1 - u) * (p01 - p00) + u * (p11 - p10)) / 0.5), 0, 1e-14);
  }
  const DerivativeBound bound = derivative_bound(patch);
  EXPECT_DOUBLE_EQ(bound.s, std::max(glm::length(p10 - p00), glm::length(p11 - p01)) / 4);
  EXPECT_DOUBLE_EQ(bound.t, std::max(glm::length(p01 - p00), glm::length(p11 - p10)) / 0.5);
  // Parameters outside the domain are clamped into it.
  EXPECT_EQ(evaluate(patch, -5, -1).position, p00);
  EXPECT_EQ(evaluate(patch, 9, 7).position, p11);
}

// Each problem invalid_reason names, on an otherwise valid patch (sphere(1): 9 x 5, degrees 2).
TEST(HostNurbsTest, InvalidReasonNamesFieldAndReason) {
  const Patch valid = sphere(1);
  ASSERT_EQ(invalid_reason(valid), "");
  auto reason = [&](auto&& change) {
    Patch patch = valid;
    change(patch);
    return invalid_reason(patch);
  };
  EXPECT_EQ(reason([](Patch& p) { p.degree_s = 4; }), "degree_s: 4 is out of range 1..3");
  EXPECT_EQ(reason([](Patch& p) { p.degree_t = 0; }), "degree_t: 0 is out of range 1..3");
  EXPECT_EQ(reason([](Patch& p) { p.count_t = 2; }),
            "count_t: 2 control points, expected at least degree_t + 1 = 3");
  EXPECT_EQ(reason([](Patch& p) { p.knots_s.pop_back(); }),
            "knots_s: 11 knots, expected count_s + degree_s + 1 = 12");
  EXPECT_EQ(reason([](Patch& p) { p.knots_s[3] = 2; }),
            "knots_s: not non-decreasing at index 4 (0.25 after 2)");
  EXPECT_EQ(reason([](Patch& p) { p.knots_t = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1}; }), "");
  EXPECT_EQ(reason([](Patch& p) { p.knots_t = {0, 0, 1, 1, 1, 1, 1, 1}; }),
            "knots_t: empty parameter domain (knots_t[2] = knots_t[5] = 1)");
  EXPECT_EQ(reason([](Patch& p) { p.knots_t[1] = NAN; }), "knots_t[1]: nan is not finite");
  EXPECT_EQ(reason([](Patch& p) { p.points.resize(44); }),
            "points: 44 control points, expected count_s * count_t = 45");
  EXPECT_EQ(reason([](Patch& p) { p.weights.push_back(1); }),
            "weights: 46 weights, expected count_s * count_t = 45");
  EXPECT_EQ(reason([](Patch& p) { p.points[16].y = INFINITY; }),
            "points[16]: (1, inf, -1) is not finite");
  EXPECT_EQ(reason([](Patch& p) { p.weights[4] = 0; }), "weights[4]: 0 must be > 0");
  EXPECT_EQ(reason([](Patch& p) { p.weights[4] = -1; }), "weights[4]: -1 must be > 0");
  EXPECT_EQ(reason([](Patch& p) { p.weights[4] = INFINITY; }), "weights[4]: inf is not finite");
}

}  // namespace
}  // namespace tmu::host::nurbs
