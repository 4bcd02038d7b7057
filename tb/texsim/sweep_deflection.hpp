// `texsim sweep deflection`: what the angular representation of 001 §4-5 costs in accuracy.
// Per setting A,E,M,W (sphere grid 2^A x 2^(A-1), angle-table index E exponents x M mantissa
// bits, coordinate-table values of W bits): the angle error (max, mean, degrees) of the
// deflected normal and of the reflection vector against the ideal model, the PSNR of a
// diffuse-shaded and of a reflection-mapped picture, the table sizes in bits, the MBR's hit
// rate and the deflection unit's cycles per pixel (and the hit rate of the same sphere
// without bumps: coherence the bumps destroy), whether each unit's RTL at that setting equals
// golden (where a Verilated model or Icarus takes it), and the Yosys cells of the three units
// (n/a beyond the RTL's ports: A <= 9, W <= 10).
//
// Workload: a scene's fragments of the materials with a deflection chain (--scene; material
// by material in frame order, each material its own deflection unit, as texsim render runs
// them; bumps from the material's height field at the texel a nearest sample reads), or by
// default a bump-mapped sphere filling a 256 x 256 view, pixels in raster order (the
// scanline coherence the cache relies on), bumps from an analytic height field. Both turn
// the bumps into bump texels (phi_D, theta_D) on each setting's grid. The hit rates count
// the bumped pixels (the only ones the deflection unit sees). Shading and reflection look the
// directions up in analytic maps (a light, a sky with a horizon and a sun), so the pictures show
// the direction errors alone, not a map's texels.
#pragma once

#include <string>

namespace tmu::texsim {

struct DeflectionSweepArgs {
  std::string settings = "8,4,5,10;9,4,5,10;10,4,5,10;9,1,7,10;9,4,6,10;9,8,6,10;9,4,5,8;9,4,5,12";
  std::string scene;    // empty: the synthetic sphere
  int size = 256;       // the synthetic view's side in pixels
  int miss_cycles = 4;  // the map memory's block latency (the tb memory model's default)
  bool synth = true;
  std::string out_dir;  // pictures per setting
  std::string markdown;
};

void sweep_deflection(const DeflectionSweepArgs& args);

}  // namespace tmu::texsim
