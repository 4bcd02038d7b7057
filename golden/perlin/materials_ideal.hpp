// The ideal (double precision) materials: the same registers read as real numbers, the ideal
// fractal sums (noise_ideal.hpp), the index computed exactly and floored once, the same
// colour tables. Measures what the noise unit's widths cost in each material's picture.
#pragma once

#include <cstdint>

#include "perlin/materials.hpp"

namespace tmu::perlin::ideal {

// The index value in table entries before the wrap (marble, wood, brick) or the clamp (fire).
double material_index(const MaterialRegs& regs, double u, double v, double w);

// RGB888.
uint32_t shade_material(const MaterialRegs& regs, const ColourTables& tables, double u, double v,
                        double w);

}  // namespace tmu::perlin::ideal
