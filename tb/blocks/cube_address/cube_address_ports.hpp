// The cube map addressing unit's ports (000 §7; rtl/deflect/tmu_cube_address.sv at its default
// SeedBits = 7, hls/deflect/cube_address_sc.hpp): the one list the RTL top, the SystemC module,
// the harness and the Icarus testbench follow (tb/harness/ports.hpp says how to read it).
#pragma once

#define TMU_PORTS_cube_address(C, F) \
  C(Sample, in)                      \
  F(In, in, x, UnitComp, 1)          \
  F(In, in, y, UnitComp, 1)          \
  F(In, in, z, UnitComp, 1)          \
  F(In, in, face_log2, MipLog2, 1)   \
  C(Result, out)                     \
  F(Out, out, face, CubeFace, 1)     \
  F(Out, out, u, TexCoord, 1)        \
  F(Out, out, v, TexCoord, 1)
