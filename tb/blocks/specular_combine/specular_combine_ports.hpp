// The specular combine's ports (000 §7 eq. 6, §8 eq. 7; rtl/texram/tmu_specular_combine.sv,
// hls/texram/specular_combine_sc.hpp): the one list the RTL top, the SystemC module, the harness
// and the Icarus testbench follow (tb/harness/ports.hpp says how to read it).
#pragma once

#define TMU_PORTS_specular_combine(C, F) \
  C(Sample, in)                          \
  F(In, in, diffuse, Rgba8888, 1)        \
  F(In, in, specular, Rgba8888, 1)       \
  F(In, in, reflectance, Rgba8888, 1)    \
  C(Result, out)                         \
  F(Out, out, colour, Rgba8888, 1)
