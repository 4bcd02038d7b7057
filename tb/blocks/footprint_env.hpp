// What the footprint assembly block (`texsim cosim footprint`) shares between its engines:
// the transaction fields and the environment (a texture in the TEXRAM's banks, the trilinear
// unit's configuration and the footprint setup's configuration).
//
// Input items: op 0 = sample (u, v: TexCoord SQ16.8; r1u, r1v, r2u, r2v: TexDeriv SQ16.8;
// shade: RGBA8888), op 1 = CLUT write (clut_addr, clut_rgba). Output: the averaged rgba, one
// per sample. Counters: the memory's (accesses, bank_reads, page_faults, slow_accesses,
// address_hash; as the trilinear block) and probes, the trilinear samples the unit made.
#pragma once

#include <cstdint>

#include "blocks/trilinear_block.hpp"
#include "footprint/footprint.hpp"

namespace tmu::tb {

enum FootprintField {
  kFpOp,
  kFpU,
  kFpV,
  kFpR1u,
  kFpR1v,
  kFpR2u,
  kFpR2v,
  kFpShade,
  kFpClutAddr,
  kFpClutRgba
};
enum FootprintOp : uint64_t { kFpOpSample = 0, kFpOpClutWrite = 1 };

struct FootprintEnv {
  TrilinearEnv trilinear;    // the texture and the trilinear unit's configuration
  footprint::Config config;  // maximum probes, q rule, setup widths
};

}  // namespace tmu::tb
