// Order pc (004 claim 15): the rasterizer interpolates a NURBS object's parameter coordinates
// (s, t) and their screen derivatives per pixel, carried in the fragment's u, v, r1 and r2 ports
// as PcCoord/PcDeriv (tau-grid cells, 16 fraction bits: the rasterizer's uv scale is 256 times
// the grid's cells); the tau unit maps them to (u, v), r1, r2 and lambda, which the trilinear
// unit or the footprint marcher then takes. Ideal applies the material's tau exactly (its
// functional map, not the grid) to the double fragment.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "blocks/tau/tau_block.hpp"
#include "raster/fragment.hpp"
#include "render/units.hpp"
#include "scene/scene.hpp"

namespace tmu::render {

// What the rasterizer scales an order-pc material's (s, t) by: 256 times the tau grid's cells.
glm::ivec2 pc_uv_scale(const host::Material& material);

// The grid the material's tau unit holds: nurbs::hardware_grid in texels of `texture_size`,
// rounded to nearest (ties to even) and saturated into TexCoord.
tb::TauGrid tau_grid(const host::Material& material, glm::ivec2 texture_size);

// Runs the material's tau unit at `level` over fragments `frags` (kept in `units` like every
// unit of a chain) and returns `records` with each of those fragments' u, v, r1, r2 and lambda
// replaced by the unit's.
std::vector<host::FragmentRecord> run_tau(const host::Material& material, glm::ivec2 texture_size,
                                          const std::vector<host::FragmentRecord>& records,
                                          const std::vector<size_t>& frags, Level level,
                                          std::vector<UnitRun>& units,
                                          std::vector<std::vector<size_t>>& outputs_of);

// The fragment with the material's tau applied in double precision: uv and r1, r2 in texels,
// lambda = log2 max(|r1|, |r2|).
host::Fragment ideal_tau(const host::Material& material, glm::ivec2 texture_size,
                         const host::Fragment& fragment);

}  // namespace tmu::render
