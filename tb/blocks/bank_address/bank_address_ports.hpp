// The TEXRAM bank address unit's ports (000 §2, Fig. 2; rtl/texram/tmu_bank_address.sv): the
// one list the RTL top and the harness follow (tb/harness/ports.hpp says how to read it). A
// combinational block: a stored position and byte plane in, its bank and cell out, under the
// texture's size, plane count and grid.
#pragma once

#define TMU_PORTS_bank_address(C, F) \
  C(CombIn, in)                      \
  F(In, in, level, MipLevel, 1)      \
  F(In, in, x, MipCoord, 1)          \
  F(In, in, y, MipCoord, 1)          \
  F(In, in, plane, BytePlane, 1)     \
  C(Cfg, cfg)                        \
  F(Cfg, cfg, log2_w, MipLog2, 1)    \
  F(Cfg, cfg, log2_h, MipLog2, 1)    \
  F(Cfg, cfg, four_planes, Flag, 1)  \
  F(Cfg, cfg, block_grid, Flag, 1)   \
  C(CombOut, out)                    \
  F(Out, out, bank, Bank, 1)         \
  F(Out, out, addr, BankAddr, 1)
