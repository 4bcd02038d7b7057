// The normal encoder's ports (001 §4.1; rtl/deflect/tmu_normal_encoder.sv at the grid A = 9,
// hls/deflect/normal_encoder_sc.hpp): the one list the RTL top, the SystemC module, the harness
// and the Icarus testbench follow (tb/harness/ports.hpp says how to read it).
#pragma once

#define TMU_PORTS_normal_encoder(C, F) \
  C(Sample, in)                        \
  F(In, in, x, UnitComp, 1)            \
  F(In, in, y, UnitComp, 1)            \
  F(In, in, z, UnitComp, 1)            \
  C(Result, out)                       \
  F(Out, out, phi, SpherePhi, 1)       \
  F(Out, out, theta, SphereTheta, 1)
