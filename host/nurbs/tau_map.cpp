#include "nurbs/tau_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tmu::host::nurbs {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

tau::GridD given_grid(const TauMap& tau) {
  tau::GridD g;
  g.cells_s = tau.cells.x;
  g.cells_t = tau.cells.y;
  for (const glm::dvec2& n : tau.nodes) {
    g.u.push_back(n.x);
    g.v.push_back(n.y);
  }
  return g;
}

// max over x in [0, 1] of sum_k |a_k(x)|, where the Catmull-Rom derivative written on the node
// differences is sum_k a_k(x) (n_{k+1} - n_k): a0 = (3x^2 - 4x + 1)/2, a1 = (-6x^2 + 6x + 1)/2,
// a2 = (3x^2 - 2x)/2 (1.5 at x = 1/2); and of sum_i |C_i(x)| for the value weights (1.25 at
// x = 1/2). Piecewise quadratics sampled at 4097 points: the sampling misses at most
// 3 h^2 / 8 < 1e-7 of the maximum, which the margin covers.
struct CatmullRomBounds {
  double derivative = 0, value = 0;
};
CatmullRomBounds catmull_rom_bounds() {
  CatmullRomBounds b;
  for (int k = 0; k <= 4096; ++k) {
    const double x = k / 4096.0, x2 = x * x, x3 = x2 * x;
    b.derivative = std::max(
        b.derivative,
        (std::abs(3 * x2 - 4 * x + 1) + std::abs(-6 * x2 + 6 * x + 1) + std::abs(3 * x2 - 2 * x)) /
            2);
    b.value = std::max(b.value, (std::abs(-x3 + 2 * x2 - x) + std::abs(3 * x3 - 5 * x2 + 2) +
                                 std::abs(-3 * x3 + 4 * x2 + x) + std::abs(x3 - x2)) /
                                    2);
  }
  b.derivative += 1e-6;
  b.value += 1e-6;
  return b;
}

// The cells [lo, hi] a normalised interval [a, b] touches on a grid of n cells.
glm::ivec2 cell_range(double a, double b, int n) {
  const auto cell = [n](double x) {
    return std::clamp(static_cast<int>(std::floor(std::clamp(x, 0.0, 1.0) * n)), 0, n - 1);
  };
  return {cell(a), cell(b)};
}

// Largest |difference| of neighbouring nodes along s (axis 0) or t (axis 1), per component,
// over the node differences of cells `si` x node rows `tj` (inclusive ranges).
glm::dvec2 max_difference(const TauMap& tau, int axis, glm::ivec2 si, glm::ivec2 tj) {
  const int row = tau.cells.x + 1;
  glm::dvec2 m(0);
  for (int j = tj.x; j <= tj.y; ++j) {
    for (int i = si.x; i <= si.y; ++i) {
      const int a = axis == 0 ? i + row * j : j + row * i;
      const int b = axis == 0 ? a + 1 : a + row;
      m = glm::max(m,
                   glm::abs(tau.nodes[static_cast<size_t>(b)] - tau.nodes[static_cast<size_t>(a)]));
    }
  }
  return m;
}

TauBound grid_bound(const TauMap& tau, double s0, double s1, double t0, double t1) {
  glm::ivec2 si = cell_range(s0, s1, tau.cells.x), ti = cell_range(t0, t1, tau.cells.y);
  double scale = 1;
  if (tau.interp == tau::Interp::kSpline) {
    // A spline cell reads the node differences one cell further on each side (the
    // extrapolated ends repeat the last difference); its weights add the basis's bounds.
    si = glm::ivec2(std::max(si.x - 1, 0), std::min(si.y + 1, tau.cells.x - 1));
    ti = glm::ivec2(std::max(ti.x - 1, 0), std::min(ti.y + 1, tau.cells.y - 1));
    static const CatmullRomBounds kBounds = catmull_rom_bounds();
    scale = kBounds.derivative * kBounds.value;
  }
  // Along s: the differences of cells si on every node row of the cells ti (and vice versa).
  TauBound b;
  b.s = scale * tau.cells.x * max_difference(tau, 0, si, {ti.x, ti.y + 1});
  b.t = scale * tau.cells.y * max_difference(tau, 1, ti, {si.x, si.y + 1});
  return b;
}

}  // namespace

TauValue evaluate(const TauMap& tau, double s, double t) {
  s = std::clamp(s, 0.0, 1.0);
  t = std::clamp(t, 0.0, 1.0);
  TauValue r;
  switch (tau.kind) {
    case TauMap::Kind::kIdentity:
      r.uv = {s, t};
      r.d_ds = {1, 0};
      r.d_dt = {0, 1};
      break;
    case TauMap::Kind::kAffine:
      r.uv = tau.matrix * glm::dvec2(s, t) + tau.offset;
      r.d_ds = tau.matrix[0];
      r.d_dt = tau.matrix[1];
      break;
    case TauMap::Kind::kWave: {
      const double a = tau.amplitude, w = kTwoPi * tau.frequency;
      r.uv = {s + a * std::sin(w * t), t + a * std::sin(w * s)};
      r.d_ds = {1, a * w * std::cos(w * s)};
      r.d_dt = {a * w * std::cos(w * t), 1};
      break;
    }
    case TauMap::Kind::kGrid: {
      const tau::MapD m =
          tau::ideal_map(given_grid(tau), tau.interp, s * tau.cells.x, t * tau.cells.y);
      r.uv = {m.u, m.v};
      r.d_ds = glm::dvec2(m.du_ds, m.dv_ds) * static_cast<double>(tau.cells.x);
      r.d_dt = glm::dvec2(m.du_dt, m.dv_dt) * static_cast<double>(tau.cells.y);
      break;
    }
  }
  return r;
}

TauBound derivative_bound(const TauMap& tau, double s0, double s1, double t0, double t1) {
  switch (tau.kind) {
    case TauMap::Kind::kIdentity:
      return {{1, 0}, {0, 1}};
    case TauMap::Kind::kAffine:
      return {glm::abs(tau.matrix[0]), glm::abs(tau.matrix[1])};
    case TauMap::Kind::kWave: {
      const double k = std::abs(kTwoPi * tau.frequency * tau.amplitude);
      return {{1, k}, {k, 1}};
    }
    case TauMap::Kind::kGrid:
      break;
  }
  return grid_bound(tau, s0, s1, t0, t1);
}

tau::GridD hardware_grid(const TauMap& tau, glm::ivec2 texture_size) {
  tau::GridD g;
  g.cells_s = tau.cells.x;
  g.cells_t = tau.cells.y;
  for (int j = 0; j <= tau.cells.y; ++j) {
    for (int i = 0; i <= tau.cells.x; ++i) {
      const glm::dvec2 uv = tau.kind == TauMap::Kind::kGrid
                                ? tau.nodes[static_cast<size_t>(i + (tau.cells.x + 1) * j)]
                                : evaluate(tau, static_cast<double>(i) / tau.cells.x,
                                           static_cast<double>(j) / tau.cells.y)
                                      .uv;
      g.u.push_back(uv.x * texture_size.x);
      g.v.push_back(uv.y * texture_size.y);
    }
  }
  return g;
}

}  // namespace tmu::host::nurbs
