#include "tau/tau_ideal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tmu::tau {
namespace {

// One axis: the stencil's first node and its weights and their derivatives in the fraction.
struct Stencil {
  int first = 0, count = 2;
  double w[4] = {0, 0, 0, 0}, dw[4] = {0, 0, 0, 0};
};

Stencil stencil(double c, int cells, Interp interp) {
  c = std::clamp(c, 0.0, static_cast<double>(cells));
  const int cell = std::min(static_cast<int>(std::floor(c)), cells - 1);
  const double x = c - cell, xx = x * x, xxx = xx * x;
  Stencil st;
  if (interp == Interp::kSpline) {  // Catmull-Rom, nodes cell - 1 .. cell + 2
    st.first = cell - 1;
    st.count = 4;
    const double w[4] = {0.5 * (-xxx + 2 * xx - x), 0.5 * (3 * xxx - 5 * xx + 2),
                         0.5 * (-3 * xxx + 4 * xx + x), 0.5 * (xxx - xx)};
    const double dw[4] = {0.5 * (-3 * xx + 4 * x - 1), 0.5 * (9 * xx - 10 * x),
                          0.5 * (-9 * xx + 8 * x + 1), 0.5 * (3 * xx - 2 * x)};
    std::copy(w, w + 4, st.w);
    std::copy(dw, dw + 4, st.dw);
  } else {  // linear, nodes cell, cell + 1
    st.first = cell;
    st.w[0] = 1 - x;
    st.w[1] = x;
    st.dw[0] = -1;
    st.dw[1] = 1;
  }
  return st;
}

// A node with the shared extrapolation rule (tau_definition.hpp) beyond the grid.
double node(const GridD& g, const std::vector<double>& n, int i, int j) {
  if (i < 0) return 2 * node(g, n, 0, j) - node(g, n, 1, j);
  if (i > g.cells_s) return 2 * node(g, n, g.cells_s, j) - node(g, n, g.cells_s - 1, j);
  if (j < 0) return 2 * node(g, n, i, 0) - node(g, n, i, 1);
  if (j > g.cells_t) return 2 * node(g, n, i, g.cells_t) - node(g, n, i, g.cells_t - 1);
  return n[static_cast<size_t>(i + (g.cells_s + 1) * j)];
}

}  // namespace

MapD ideal_map(const GridD& g, Interp interp, double s, double t) {
  const size_t nodes = static_cast<size_t>(g.cells_s + 1) * static_cast<size_t>(g.cells_t + 1);
  if (g.cells_s < 1 || g.cells_t < 1 || g.u.size() != nodes || g.v.size() != nodes) {
    throw std::invalid_argument(
        "tau::ideal_map: a grid needs cells >= 1 and (cells_s + 1) "
        "(cells_t + 1) nodes of u and of v");
  }
  const Stencil a = stencil(s, g.cells_s, interp), b = stencil(t, g.cells_t, interp);
  MapD m;
  for (int q = 0; q < b.count; ++q) {
    const int j = b.first + q;
    for (int p = 0; p < a.count; ++p) {
      const int i = a.first + p;
      const double nu = node(g, g.u, i, j), nv = node(g, g.v, i, j);
      const double w = a.w[p] * b.w[q], ws = a.dw[p] * b.w[q], wt = a.w[p] * b.dw[q];
      m.u += w * nu;
      m.v += w * nv;
      m.du_ds += ws * nu;
      m.dv_ds += ws * nv;
      m.du_dt += wt * nu;
      m.dv_dt += wt * nv;
    }
  }
  return m;
}

IdealResult ideal_sample(const GridD& g, Interp interp, double s, double t, double ds_dx,
                         double dt_dx, double ds_dy, double dt_dy) {
  const MapD m = ideal_map(g, interp, s, t);
  IdealResult r;
  r.u = m.u;
  r.v = m.v;
  r.r1u = m.du_ds * ds_dx + m.du_dt * dt_dx;
  r.r1v = m.dv_ds * ds_dx + m.dv_dt * dt_dx;
  r.r2u = m.du_ds * ds_dy + m.du_dt * dt_dy;
  r.r2v = m.dv_ds * ds_dy + m.dv_dt * dt_dy;
  const double longer = std::max(std::hypot(r.r1u, r.r1v), std::hypot(r.r2u, r.r2v));
  r.lambda = longer > 0 ? std::log2(longer) : -std::numeric_limits<double>::infinity();
  return r;
}

}  // namespace tmu::tau
