// The ideal (double precision) tau mapping (004: EP0637814 claims 4-6, 15): the map from
// parameter coordinates (s, t) to texture coordinates (u, v) through a grid of nodes, exact
// bilinear (claim 5) or Catmull-Rom (claim 6) interpolation with its Jacobian, and the
// footprint vectors r1, r2 and lambda it gives a pixel. Its own code throughout: it shares with
// golden only the grid's definition and the extrapolation rule (tau_definition.hpp). The host's
// renderer calls ideal_map for vertex texture coordinates and reference images.
#pragma once

#include <vector>

#include "tau/tau_definition.hpp"

namespace tmu::tau {

// Nodes in texels, (cells_s + 1) (cells_t + 1) of them, node (i, j) at i + (cells_s + 1) j.
struct GridD {
  int cells_s = 1, cells_t = 1;
  std::vector<double> u, v;
};

// (u, v) at (s, t) and its partial derivatives, texels per cell.
struct MapD {
  double u = 0, v = 0, du_ds = 0, dv_ds = 0, du_dt = 0, dv_dt = 0;
};

// s, t in cells, clamped to [0, cells]; beyond the grid the clamped point's value and Jacobian.
MapD ideal_map(const GridD& grid, Interp interp, double s, double t);

struct IdealResult {
  double u = 0, v = 0;      // texels
  double r1u = 0, r1v = 0;  // d(u, v)/dx, texels per pixel
  double r2u = 0, r2v = 0;  // d(u, v)/dy
  double lambda = 0;        // log2 max(|r1|, |r2|); -infinity when both are zero
};
IdealResult ideal_sample(const GridD& grid, Interp interp, double s, double t, double ds_dx,
                         double dt_dx, double ds_dy, double dt_dy);

}  // namespace tmu::tau
