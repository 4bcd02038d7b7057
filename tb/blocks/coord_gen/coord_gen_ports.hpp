// The coordinate generator's ports (001 §5; rtl/deflect/tmu_coord_gen.sv,
// hls/deflect/coord_gen_sc.hpp): the one list the RTL top, the SystemC module, the harness and
// the Icarus testbench follow (tb/harness/ports.hpp says how to read it). A smaller grid or
// entry width (the RTL's parameters) uses the ports' low bits.
#pragma once

#define TMU_PORTS_coord_gen(C, F)    \
  C(Write, tw)                       \
  F(In, tw, table, CoordTableId, 1)  \
  F(In, tw, addr, CoordTableAddr, 1) \
  F(In, tw, value, CoordValue, 1)    \
  C(Sample, in)                      \
  F(In, in, phi, SpherePhi, 1)       \
  F(In, in, theta, SphereTheta, 1)   \
  C(Result, out)                     \
  F(Out, out, un, UnitComp, 1)       \
  F(Out, out, vn, UnitComp, 1)       \
  F(Out, out, ur, UnitComp, 1)       \
  F(Out, out, vr, UnitComp, 1)       \
  F(Out, out, wr, UnitComp, 1)
