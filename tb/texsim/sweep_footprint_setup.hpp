// `texsim sweep footprint-setup`: the footprint unit's setup (000 §10 eq. 19-20: lengths, the
// ratio and the logarithm) at each width setting D,T,F (footprint::Widths: derivative bits,
// log2 table bits, log fraction bits): lambda's error and how often N differs from the ideal
// setup's, on random footprints; the golden setup's speed; whether the RTL at that setting,
// where the build verilated it, equals golden; the Yosys figures of tmu_footprint_setup at that
// setting (docs/footprint.md).
#pragma once

#include <string>

namespace tmu::texsim {

struct FootprintSetupSweepArgs {
  // 16,10,12 and 8,4,5 too: tmu_footprint has Verilated variants of them, so their rows are
  // simulated against golden, not synthesized only.
  std::string settings = "24,10,12;16,10,12;16,8,10;12,7,8;12,6,8;10,6,8;8,5,8;8,4,5;12,4,6;6,3,4";
  int count = 200000;  // random footprints per setting
  bool synth = true;
  std::string markdown;
};

void sweep_footprint_setup(const FootprintSetupSweepArgs& args);

}  // namespace tmu::texsim
