// The rows the TEXRAM sampling path's tops share (rtl/texram/tmu_trilinear.sv and
// rtl/footprint/tmu_footprint.sv, which contains it): the trilinear unit's configuration with
// what the memory holds, and the eight banks. Written once, in the same order in both
// descriptions, so that the two blocks' configuration and memory slots are the same and one
// environment and one golden sampler serve both (tb/harness/ports.hpp says how to read rows).
#pragma once

// The configuration: the texture's size and texel kind, the output channel of a single-component
// texture, the filter, the border operator per axis and its colour, eq. 5's selection and k_T;
// then what the memory holds (not ports): the texture's content and the seed it is drawn from.
#define TMU_PORTS_texram_cfg(C, F)          \
  F(Cfg, cfg, log2_w, MipLog2, 1)           \
  F(Cfg, cfg, log2_h, MipLog2, 1)           \
  F(Cfg, cfg, kind, TexKind, 1)             \
  F(Cfg, cfg, single_channel, BytePlane, 1) \
  F(Cfg, cfg, filter, TexFilter, 1)         \
  F(Cfg, cfg, border_u, TexBorder, 1)       \
  F(Cfg, cfg, border_v, TexBorder, 1)       \
  F(Cfg, cfg, border_rgba, Rgba8888, 1)     \
  F(Cfg, cfg, combine, TexCombine, 1)       \
  F(Cfg, cfg, constant_rgba, Rgba8888, 1)   \
  F(Env, cfg, pattern, EnvPattern, 1)       \
  F(Env, cfg, content, EnvSeed, 1)

// One access of the eight banks (bank b enabled by en<b>, at addr<b>) and its response (bank
// b's byte in data<b>), in request order.
#define TMU_PORTS_texram_memory(C, F) \
  C(MemRequest, mem_req)              \
  F(Req, mem_req, en, Flag, 8)        \
  F(Req, mem_req, addr, BankAddr, 8)  \
  C(MemResponse, mem_resp)            \
  F(Resp, mem_resp, data, BankByte, 8)
