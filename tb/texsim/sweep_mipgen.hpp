// `texsim sweep mipgen`: the mipmap generator's rounding rule (000 §12; texram/mipmap.hpp) at
// each carry: every level's error against the ideal pyramid (the exact box means of level 0,
// texram/mipmap_ideal.hpp) on the R, G and B planes of an image, what the carried bits cost in
// the generator's registers and line FIFOs (at the largest texture, 1024 a side), whether the
// RTL equals golden (verilated at the exact carry only), and the Yosys figures of tmu_mipgen at
// that CarryBits (docs/texram.md, "The pyramid's rounding").
#pragma once

#include <string>

namespace tmu::texsim {

struct MipgenSweepArgs {
  std::string settings = "0;1;2;3;4;6;8;20";  // carries, 0..20 (20: every sum exact)
  std::string image;                          // default: the bundled photo-like field, 512 x 512
  bool synth = true;
  std::string markdown;
};

void sweep_mipgen(const MipgenSweepArgs& args);

}  // namespace tmu::texsim
