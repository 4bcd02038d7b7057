// The TEXRAM trilinear unit's ports (000 §2, §5, §6; rtl/texram/tmu_trilinear.sv,
// hls/texram/trilinear_sc.hpp): the one list the RTL top, the SystemC module and the harness
// follow (tb/harness/ports.hpp says how to read it). The configuration and the memory rows are
// the ones footprint shares (texram_ports.hpp).
#pragma once

#include "blocks/trilinear/texram_ports.hpp"

#define TMU_PORTS_trilinear(C, F)                                         \
  C(Sample, req)                                                          \
  F(In, req, u, TexCoord, 1)                                              \
  F(In, req, v, TexCoord, 1)                                              \
  F(In, req, lambda, Lod, 1)                                              \
  F(In, req, shade, Rgba8888, 1)                                          \
  C(Write, clut)                                                          \
  F(In, clut, addr, ClutIndex, 1)                                         \
  F(In, clut, rgba, Rgba8888, 1)                                          \
  C(Cfg, cfg)                                                             \
  TMU_PORTS_texram_cfg(C, F) TMU_PORTS_texram_memory(C, F) C(Result, out) \
      F(Out, out, rgba, Rgba8888, 1)
