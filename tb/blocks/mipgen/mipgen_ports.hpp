// The mipmap generator's ports (000 §12, Fig. 14; rtl/texram/tmu_mipgen.sv,
// hls/texram/mipgen_sc.hpp): the one list the RTL top, the SystemC module and the harness
// follow (tb/harness/ports.hpp says how to read it). The frame format is the configuration,
// written between frames; a texel item gives as many writes as its place in the frame makes.
#pragma once

#define TMU_PORTS_mipgen(C, F)      \
  C(Cfg, cfg)                       \
  F(Cfg, cfg, log2_w, MipLog2, 1)   \
  F(Cfg, cfg, log2_h, MipLog2, 1)   \
  F(Cfg, cfg, interlaced, Flag, 1)  \
  F(Cfg, cfg, four_planes, Flag, 1) \
  F(Cfg, cfg, plane, BytePlane, 1)  \
  C(Stream, in)                     \
  F(In, in, texel, Channel, 1)      \
  F(In, in, above, Channel, 1)      \
  C(Result, wr)                     \
  F(Out, wr, level, MipLevel, 1)    \
  F(Out, wr, x, MipCoord, 1)        \
  F(Out, wr, y, MipCoord, 1)        \
  F(Out, wr, value, Channel, 1)     \
  F(Out, wr, bank, Bank, 1)         \
  F(Out, wr, addr, BankAddr, 1)
