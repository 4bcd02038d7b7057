// `texsim sweep perlin`: what the noise unit's widths cost (002 ch. 4). Per setting F,S,B,X
// (coordinate fraction bits, fade-table index and entry bits, lerp fraction bits beyond the
// lattice values'): the noise's and the fractal sums' error against the ideal (max, mean),
// the PSNR of each of the scene's procedural materials on a slice of solid space, the fade
// table's bits, the golden model's ns per sample, whether the RTL equals golden (verilated at
// the default setting only) and the Yosys cells and depth of tmu_noise at that setting. Then
// the two fractal configurations at the default setting: cells against cycles per sample, both
// measured on their RTL against golden.
#pragma once

#include <string>

namespace tmu::texsim {

struct PerlinSweepArgs {
  std::string settings = "8,8,8,4;4,4,4,0;6,6,6,2;8,6,8,4;8,8,6,4;8,8,8,0;8,8,8,8;12,10,12,8";
  std::string scene;    // its procedural materials; empty: scenes/procedural.json
  int points = 100000;  // random points for the error statistics
  int size = 128;       // the slice's side in pixels
  bool synth = true;
  std::string out_dir;  // pictures per setting and material
  std::string markdown;
};

void sweep_perlin(const PerlinSweepArgs& args);

}  // namespace tmu::texsim
