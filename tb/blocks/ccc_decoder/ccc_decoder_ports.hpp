// The CCC decoder's ports (000 §3, Fig. 5; rtl/ccc/tmu_ccc_decoder.sv,
// hls/ccc/ccc_decoder_sc.hpp): the one list the RTL top, the SystemC module, the harness and the
// Icarus testbench follow (tb/harness/ports.hpp says how to read it). The request channel comes
// first so that op 0 is a decode and op 1 a CLUT write, and the input fields keep the names
// (block, texel, clut_addr, clut_rgb) that vector files saved before the description have.
#pragma once

#define TMU_PORTS_ccc_decoder(C, F) \
  C(Sample, req)                    \
  F(In, req, block, CccBlock, 1)    \
  F(In, req, texel, CccTexel, 1)    \
  C(Write, clut)                    \
  F(In, clut, addr, ClutIndex, 1)   \
  F(In, clut, rgb, Rgb888, 1)       \
  C(Result, out)                    \
  F(Out, out, rgb, Rgb888, 1)
