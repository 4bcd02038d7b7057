// The noise unit's ports (002 §4.1; rtl/perlin/tmu_noise.sv, hls/perlin/noise_sc.hpp): the
// one list the RTL top, the SystemC module, the harness and the Icarus testbench follow
// (tb/harness/ports.hpp says how to read it).
#pragma once

#define TMU_PORTS_noise(C, F) \
  C(Sample, in)               \
  F(In, in, u, SolidCoord, 1) \
  F(In, in, v, SolidCoord, 1) \
  F(In, in, w, SolidCoord, 1) \
  C(Result, out)              \
  F(Out, out, p, NoiseValue, 1)
