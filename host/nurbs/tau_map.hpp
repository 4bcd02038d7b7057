// The tau mapping of 004 (claims 3-6): parameter coordinates (s, t) of an object, normalised
// to [0, 1] over the object's parameter rectangle, to texture coordinates (u, v) in texture
// units (1 = one texture across, as every uv of a scene). Double precision on the host: the
// vertices' texture coordinates (claims 16-18) and the reference images (ideal) come from here;
// per pixel in hardware (claim 15), the tau unit interpolates the grid `hardware_grid` gives.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "tau/tau_ideal.hpp"

namespace tmu::host::nurbs {

struct TauMap {
  enum class Kind {
    kIdentity,  // u = s, v = t
    kAffine,    // (u, v) = matrix (s, t) + offset (claim 3)
    kWave,      // u = s + A sin(2 pi f t), v = t + A sin(2 pi f s): a non-linear map (claim 3)
    kGrid,      // nodes given at a regular grid of (s, t), interpolated (claims 4-6)
  };
  Kind kind = Kind::kIdentity;
  glm::dmat2 matrix{1.0};  // kAffine: columns are d(u, v)/ds and d(u, v)/dt
  glm::dvec2 offset{0.0};
  double amplitude = 0.05, frequency = 2;  // kWave
  // kGrid: (cells.x + 1) x (cells.y + 1) nodes (u, v), index i + (cells.x + 1) j, i along s.
  std::vector<glm::dvec2> nodes;
  // kGrid: the given grid's cells; otherwise the grid the tau unit holds (claim 15), the map
  // sampled at its nodes. Each 1..tau::kMaxCells.
  glm::ivec2 cells{8, 8};
  tau::Interp interp = tau::Interp::kLinear;  // how a grid is interpolated (claims 5, 6)
};

// tau and its Jacobian at normalised (s, t) (clamped into [0, 1]).
struct TauValue {
  glm::dvec2 uv{0};
  glm::dvec2 d_ds{0}, d_dt{0};  // d(u, v)/ds, d(u, v)/dt per unit of normalised s, t
};
TauValue evaluate(const TauMap& tau, double s, double t);

// Bounds of |du/ds|, |dv/ds| (in .s) and |du/dt|, |dv/dt| (in .t) over the normalised
// rectangle [s0, s1] x [t0, t1], each component separately (claims 9, 12: ||tau'_s||, the
// maximum derivative bound). Exact for identity and affine maps and for a linear grid (a
// bilinear cell's derivative is largest on its edges); for the wave the global maximum; for a
// spline grid the node differences times the Catmull-Rom basis's bound (tau_map.cpp).
struct TauBound {
  glm::dvec2 s{0}, t{0};
};
TauBound derivative_bound(const TauMap& tau, double s0, double s1, double t0, double t1);

// The grid the tau unit holds for this map (claim 15): the given nodes of a grid map, or the
// map sampled at the nodes of `cells` (exact at the nodes; between them the hardware
// interpolates). In texels: u times width, v times height.
tau::GridD hardware_grid(const TauMap& tau, glm::ivec2 texture_size);

}  // namespace tmu::host::nurbs
