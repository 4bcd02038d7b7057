// The ideal (double precision) materials: the same registers read as real numbers, the ideal
// fractal sums (noise_ideal.hpp), the index computed exactly and floored once, the brick
// geometry on the exact coordinates, the same colour tables. Measures what the noise unit's
// widths cost in each material's picture.
//
// It shares with golden only the definitions of material_definition.hpp (the registers and
// the colour tables) and noise_definition.hpp (SolidCoord's fraction, which scales the brick
// registers); all arithmetic is its own.
#pragma once

#include <cstdint>

#include "perlin/material_definition.hpp"

namespace tmu::perlin::ideal {

// The brick test of materials.hpp at exact (u, v) in units: golden's on SolidCoord's grid,
// where the two agree; between grid points the exact joint edge can fall inside a raw unit
// that golden's floor gives to the joint.
bool in_brick(const MaterialRegs& regs, double u, double v);

// The index value in table entries before the wrap (marble, wood, brick) or the clamp (fire).
double material_index(const MaterialRegs& regs, double u, double v, double w);

// RGB888.
uint32_t shade_material(const MaterialRegs& regs, const ColourTables& tables, double u, double v,
                        double w);

}  // namespace tmu::perlin::ideal
