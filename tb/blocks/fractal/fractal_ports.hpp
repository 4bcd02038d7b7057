// The fractal sums' ports (002 §4.1.1; rtl/perlin/tmu_fractal_pipelined.sv and
// tmu_fractal_shared.sv, the same ports; hls/perlin/fractal_sc.hpp): the one list the RTL tops,
// the SystemC module, the harness and the Icarus testbench follow (tb/harness/ports.hpp).
#pragma once

#define TMU_PORTS_fractal(C, F)     \
  C(Sample, in)                     \
  F(In, in, u, SolidCoord, 1)       \
  F(In, in, v, SolidCoord, 1)       \
  F(In, in, w, SolidCoord, 1)       \
  C(Result, out)                    \
  F(Out, out, sum, FractalValue, 1) \
  F(Out, out, turbulence, FractalValue, 1)
