// The low-cost CCC unit's ports (000 §4, Figs. 6-7; rtl/ccc/tmu_ccc_cache_bilinear.sv,
// hls/ccc/ccc_cache_bilinear_sc.hpp): the one list the RTL top, the SystemC module and the
// harness follow (tb/harness/ports.hpp says how to read it). The texture seed is the
// environment's: the memory holds the texture it names.
#pragma once

#define TMU_PORTS_ccc_cache_bilinear(C, F) \
  C(Sample, req)                           \
  F(In, req, u, TexCoord, 1)               \
  F(In, req, v, TexCoord, 1)               \
  C(Write, clut)                           \
  F(In, clut, addr, ClutIndex, 1)          \
  F(In, clut, rgb, Rgb888, 1)              \
  C(Cfg, cfg)                              \
  F(Cfg, cfg, width, TexSize, 1)           \
  F(Cfg, cfg, height, TexSize, 1)          \
  F(Cfg, cfg, lookahead, Flag, 1)          \
  F(Env, cfg, texture, EnvSeed, 1)         \
  C(MemRequest, mem_req)                   \
  F(Req, mem_req, addr, CccBlockAddr, 1)   \
  C(MemResponse, mem_resp)                 \
  F(Resp, mem_resp, block, CccBlock, 1)    \
  C(Result, out)                           \
  F(Out, out, rgb, Rgb888, 1)              \
  C(Stat, stat)                            \
  F(Stat, stat, hits, StatCount, 1)        \
  F(Stat, stat, misses, StatCount, 1)      \
  F(Stat, stat, prefetches, StatCount, 1)
