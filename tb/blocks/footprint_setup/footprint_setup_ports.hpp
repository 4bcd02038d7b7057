// The footprint setup's ports (000 §10, eq. 19-22; rtl/footprint/tmu_footprint_setup.sv, the
// setup tmu_footprint instantiates): the one list the RTL top and the harness follow
// (tb/harness/ports.hpp says how to read it). A fragment in, its plan out: the centre, the
// marching direction, the shade, k = log2 N and the probes' lambda. stat_busy_o (a fragment in
// a stage) is read at the end of a run, when the setup must be empty.
#pragma once

#define TMU_PORTS_footprint_setup(C, F)      \
  C(Sample, req)                             \
  F(In, req, u, TexCoord, 1)                 \
  F(In, req, v, TexCoord, 1)                 \
  F(In, req, r1u, TexDeriv, 1)               \
  F(In, req, r1v, TexDeriv, 1)               \
  F(In, req, r2u, TexDeriv, 1)               \
  F(In, req, r2v, TexDeriv, 1)               \
  F(In, req, shade, Rgba8888, 1)             \
  C(Cfg, cfg)                                \
  F(Cfg, cfg, log2_max_probes, ProbeLog2, 1) \
  F(Cfg, cfg, q_rule, QRule, 1)              \
  C(Result, plan)                            \
  F(Out, plan, u, TexCoord, 1)               \
  F(Out, plan, v, TexCoord, 1)               \
  F(Out, plan, du, TexDeriv, 1)              \
  F(Out, plan, dv, TexDeriv, 1)              \
  F(Out, plan, shade, Rgba8888, 1)           \
  F(Out, plan, log2_n, ProbeLog2, 1)         \
  F(Out, plan, lambda, Lod, 1)               \
  C(Stat, stat)                              \
  F(Stat, stat, busy, Flag, 1)
