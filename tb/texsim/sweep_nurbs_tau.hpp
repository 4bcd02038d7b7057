// `texsim sweep nurbs`, the tau unit's grid (004 claims 4-6, 15): per grid size and
// interpolation, how far the unit's (u, v) and lambda are from the functional map it stands
// for, and its rtl against golden with its cycles per sample.
//
// The map is the wave (u = s + 0.05 sin(2 pi 1.5 t), v alike; 256 x 256 texels), fixed rather
// than a scene's so that the rows compare grids, not scenes. The unit is golden's tau::TauUnit
// loaded with the grid a render loads (render/tau_stage.cpp tau_grid: the map sampled at the
// nodes, rounded to TexCoord); the exact figures are nurbs::evaluate at the (s, t) and
// derivatives the unit was given (after their rounding to the ports), so an error is the grid's
// and the unit's arithmetic, not the ports'. The affine rows show the arithmetic alone: an
// affine map with nodes on the TexCoord grid, sampled where the unit's 12-bit weights are
// exact, comes out exact in either interpolation (Catmull-Rom reproduces linear functions).
#pragma once

#include <cstddef>

#include "texsim/sweep_support.hpp"

namespace tmu::texsim {

// `samples` random (s, t) and derivative pairs per row; the first `rtl_items` of them also
// through the tau block at rtl and golden.
SweepTable tau_grid_table(size_t samples, size_t rtl_items);

}  // namespace tmu::texsim
