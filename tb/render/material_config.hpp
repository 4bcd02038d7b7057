// A scene's procedural material as the material unit's registers and colour tables
// (golden/perlin/material_unit.hpp): the host's side of the write port.
#pragma once

#include "perlin/materials.hpp"
#include "scene/scene.hpp"

namespace tmu::render {

// Each physical value rounded to its register's fixed point and clamped to its range.
perlin::MaterialRegs material_registers(const host::Procedural& procedural);
perlin::ColourTables material_tables(const host::Procedural& procedural);

}  // namespace tmu::render
