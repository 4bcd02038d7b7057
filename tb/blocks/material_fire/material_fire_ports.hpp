// The ports of fire's e^-v table (002 §4.2.2; rtl/perlin/tmu_material_fire.sv, a
// combinational top without clock or reset): the one list the RTL top, the harness and the
// Icarus testbench follow (tb/harness/ports.hpp says how to read it).
#pragma once

#define TMU_PORTS_material_fire(C, F) \
  C(CombIn, in)                       \
  F(In, in, k, FireIndex, 1)          \
  C(CombOut, out)                     \
  F(Out, out, entry, FireEntry, 1)
