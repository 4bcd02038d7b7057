// Golden model of the tau unit (004: EP0637814, claims 4-6 and 15): a NURBS object's parameter
// coordinates (s, t), interpolated per pixel by the rasterizer, are mapped to texture
// coordinates (u, v) through the tau mapping, a grid of (u, v) nodes held in a memory, and the
// screen derivatives of (s, t) are mapped through tau's Jacobian to r1 = d(u,v)/dx,
// r2 = d(u,v)/dy and lambda = log2 max(|r1|, |r2|), what the trilinear unit and the footprint
// marcher take. This comment is the specification the hls and rtl models match.
//
// Formats (golden/formats/formats.def): s, t PcCoord SQ8.16 in grid cells; ds/dx, dt/dx, ds/dy,
// dt/dy PcDeriv SQ8.16 cells per pixel; nodes u, v TexCoord SQ16.8 texels; out u, v TexCoord,
// r1u, r1v, r2u, r2v TexDeriv SQ16.8, lambda Lod SQ6.8. All arithmetic is on integers.
//
// Configuration: cells_s, cells_t (TauCells: 0 acts as 1, above 16 as 16), interp (TauInterp:
// linear, claim 5, or Catmull-Rom, claim 6). The memory: node (i, j) at address i + 17 j
// (tau_definition.hpp); a write to 289 .. 511 is ignored; a node holds the port's 24 bits (a
// value outside SQ16.8 is wrapped, as the port would). A sample that reads a node no write has
// set throws (the memory is a RAM without reset).
//
// Per sample, per axis (s with cells_s; t alike):
// 1. Clamp s into [0, cells 2^16] (raw). Cell i = min(s >> 16, cells - 1); the fraction
//    x = (s - i 2^16) >> 4, a 12-bit weight fraction, x = 2^12 only at s = cells (13 bits).
//    Truncated: x / 2^12 is below the exact fraction by less than 2^-12 cell.
// 2. x2 = (x x + 2^11) >> 12, x3 = (x2 x + 2^11) >> 12 (the only roundings of the weights).
//    Weights in units of 2^-13 (one = 2^13), per cell:
//    Catmull-Rom, nodes i - 1, i, i + 1, i + 2:
//      C0 = -x3 + 2 x2 - x,  C1 = 3 x3 - 5 x2 + 2^13,  C2 = -3 x3 + 4 x2 + x,  C3 = x3 - x2
//      (sum exactly 2^13), and their derivatives d/ds (units 2^-13 per cell):
//      D0 = -3 x2 + 4 x - 2^12,  D1 = 9 x2 - 10 x,  D2 = -9 x2 + 8 x + 2^12,  D3 = 3 x2 - 2 x
//      (sum exactly 0).
//    Linear, nodes i, i + 1: C = (2 (2^12 - x), 2 x), D = (-2^13, 2^13) (exact).
// 3. A node the stencil reaches outside the grid (index -1 or cells + 1: the spline only) is
//    extrapolated linearly (tau_definition.hpp), exactly: its value needs 28 bits signed
//    (|n| <= 9 2^23: a corner is 4 n00 - 2 n10 - 2 n01 + n11), so nothing saturates there.
// 4. U = sum_ij Cs_i Ct_j n_ij (units 2^-26 of a node's raw SQ16.8 value), u = round half up
//    (U / 2^26) = (U + 2^25) >> 26, saturated to TexCoord. The Jacobian: Us = sum Ds_i Ct_j
//    n_ij, Ut = sum Cs_i Dt_j n_ij, rounded half up to SQ18.10 texels per cell
//    (Jus = (Us + 2^23) >> 24) and saturated to 28 bits signed. V, Vs, Vt alike. Every sum is
//    exact: |U| < 2^50, |Us|, |Ut| < 2^51 (the weights with the extrapolation
//    moved onto in-grid nodes, tmu_tau_weights, sum to at most 10240 and 24576 in absolute).
// 5. r1u = round half up ((Jus ds/dx + Jut dt/dx) / 2^18) -> TexDeriv saturated; r1v with V's
//    Jacobian; r2u, r2v with ds/dy, dt/dy.
// 6. lambda = log2 |r_max| exactly as the footprint setup computes it (golden
//    footprint::plan, widths D 12, T 7, F 8, with at most one probe and the sides rule, where
//    its lambda is log2 |r_max| itself): sh = max(0, bitlen(max |component of r1, r2|) - 12),
//    components |c| >> sh, smax = max(r1u'^2 + r1v'^2, r2u'^2 + r2v'^2),
//    lg = footprint::log2_fixed(smax, {12, 7, 8}), lambda in 9 fraction bits
//    = lg + 2 sh 2^8 - 16 2^8, rounded half up to SQ6.8 ((x + 1) >> 1, arithmetic) and
//    saturated to Lod; smax = 0 (r1 = r2 = 0) gives the smallest Lod.
// Beyond the grid (s < 0 or s > cells) the sample is the edge's: (u, v) and the Jacobian of the
// clamped point (the texture stretches; its footprint does not collapse to zero).
#pragma once

#include <array>
#include <bitset>
#include <cstdint>

#include "tau/tau_definition.hpp"

namespace tmu::tau {

struct Config {
  int cells_s = 1, cells_t = 1;
  Interp interp = Interp::kLinear;
};

// Raw port values: s, t PcCoord; the derivatives PcDeriv.
struct Request {
  int32_t s = 0, t = 0, ds_dx = 0, dt_dx = 0, ds_dy = 0, dt_dy = 0;
};

// Raw port values: u, v TexCoord; r1u .. r2v TexDeriv; lambda Lod.
struct Result {
  int32_t u = 0, v = 0, r1u = 0, r1v = 0, r2u = 0, r2v = 0, lambda = 0;
  friend bool operator==(const Result&, const Result&) = default;
};

// Steps 1-2 along one axis: the cell, the fraction, and the weights of the stencil's nodes
// first .. first + count - 1 (first = cell - 1 and count 4 for the spline, cell and 2 linear).
struct AxisWeights {
  int cell = 0;
  int32_t x = 0, x2 = 0, x3 = 0;
  int first = 0, count = 2;
  std::array<int32_t, 4> c{}, d{};
};
AxisWeights axis_weights(int32_t coord, int cells, Interp interp);

// The configuration as the unit sees it: cells clamped into 1..16.
int effective_cells(int cells);

// What a sample computes on its way (for tests and coverage).
struct Trace {
  AxisWeights s, t;
  int64_t sum_u = 0, sum_v = 0;                // U, V
  int64_t sum_us = 0, sum_vs = 0;              // Us, Vs
  int64_t sum_ut = 0, sum_vt = 0;              // Ut, Vt
  int32_t jus = 0, jvs = 0, jut = 0, jvt = 0;  // SQ18.10 texels per cell, saturated
  bool extrapolated = false;                   // the stencil reached beyond the grid
  bool uv_saturated = false, j_saturated = false, r_saturated = false;
  Result result;
};

class TauUnit {
 public:
  void configure(const Config& config);
  const Config& config() const { return config_; }
  // Node (i, j) at addr = i + 17 j; u, v raw SQ16.8 (the port's 24 bits).
  void write(uint32_t addr, int32_t u, int32_t v);
  Result sample(const Request& request) const { return trace(request).result; }
  Trace trace(const Request& request) const;
  // A node's value with the extrapolation rule, for i in -1 .. cells_s + 1, j in -1 ..
  // cells_t + 1 (raw SQ16.8 units, 28 bits); `v` picks the v component.
  int64_t node(int i, int j, bool v) const;

 private:
  Config config_;
  std::array<int32_t, kNodes> u_{}, v_{};
  std::bitset<kNodes> written_;
};

}  // namespace tmu::tau
