// A procedural material's units (002 §4.2): the material unit, loaded with the material's
// registers and colour tables through its write port, then eq. 5's product with the vertex
// shade (combine "shade"), done by the specular_combine unit with C_d = 0 and R = I_d:
//   material            (u, v, w) SolidCoord          -> P, RGB888
//   specular_combine    C = 0 + I_d . P               (combine shade only)
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "render/effect_chain.hpp"

namespace tmu::render {

// Runs the units at in.level (not ideal); appends them to `units` / `outputs_of` like
// run_effect_chain. Returns RGBA8888 per in.frags entry.
std::vector<uint32_t> run_procedural(const ChainInput& in, std::vector<UnitRun>& units,
                                     std::vector<std::vector<size_t>>& outputs_of);

// The ideal: ideal::shade_material at the exact solid coordinates, times the exact shade.
std::vector<glm::dvec4> ideal_procedural(const ChainInput& in,
                                         const std::vector<host::Fragment>& fragments);

}  // namespace tmu::render
