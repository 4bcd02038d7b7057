// The material unit's ports (002 §4.2; rtl/perlin/tmu_material.sv, both configurations the
// same ports; hls/perlin/material_sc.hpp): the one list the RTL top, the SystemC module, the
// harness and the Icarus testbench follow (tb/harness/ports.hpp says how to read it). The
// sample channel comes first so that its fields keep their names (u, v, w) and the write
// channel's own op field is wr_op, apart from the item's op (0 a sample, 1 a write).
#pragma once

#define TMU_PORTS_material(C, F)        \
  C(Sample, in)                         \
  F(In, in, u, SolidCoord, 1)           \
  F(In, in, v, SolidCoord, 1)           \
  F(In, in, w, SolidCoord, 1)           \
  C(Write, wr)                          \
  F(In, wr, op, MaterialWriteOp, 1)     \
  F(In, wr, reg, MaterialRegId, 1)      \
  F(In, wr, value, MaterialRegValue, 1) \
  F(In, wr, table, MaterialTable, 1)    \
  F(In, wr, index, MaterialEntry, 1)    \
  F(In, wr, rgb, Rgb888, 1)             \
  C(Result, out)                        \
  F(Out, out, rgb, Rgb888, 1)
