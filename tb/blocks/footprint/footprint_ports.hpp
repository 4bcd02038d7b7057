// The footprint assembly unit's ports (000 §10, eq. 19-22; rtl/footprint/tmu_footprint.sv,
// hls/footprint/footprint_sc.hpp): the one list the RTL top, the SystemC module and the harness
// follow (tb/harness/ports.hpp says how to read it). Its trilinear unit's configuration and
// memory rows are the trilinear block's (tb/blocks/trilinear/texram_ports.hpp, in the same
// slots), then the setup's configuration.
#pragma once

#include "blocks/trilinear/texram_ports.hpp"

#define TMU_PORTS_footprint(C, F)                                                \
  C(Sample, req)                                                                 \
  F(In, req, u, TexCoord, 1)                                                     \
  F(In, req, v, TexCoord, 1)                                                     \
  F(In, req, r1u, TexDeriv, 1)                                                   \
  F(In, req, r1v, TexDeriv, 1)                                                   \
  F(In, req, r2u, TexDeriv, 1)                                                   \
  F(In, req, r2v, TexDeriv, 1)                                                   \
  F(In, req, shade, Rgba8888, 1)                                                 \
  C(Write, clut)                                                                 \
  F(In, clut, addr, ClutIndex, 1)                                                \
  F(In, clut, rgba, Rgba8888, 1)                                                 \
  C(Cfg, cfg)                                                                    \
  TMU_PORTS_texram_cfg(C, F) F(Cfg, cfg, log2_max_probes, ProbeLog2, 1)          \
      F(Cfg, cfg, q_rule, QRule, 1) TMU_PORTS_texram_memory(C, F) C(Result, out) \
          F(Out, out, rgba, Rgba8888, 1) C(Stat, stat) F(Stat, stat, probes, StatCount, 1)
