// `texsim sweep volume`: what the volume unit's weight bits and the ray's step cost (000 §13).
// Per setting W,step on a volume scene (default scenes/volume_marschner_lobb.json, the standard
// reconstruction test) rendered without early termination at golden and at ideal: the resamples'
// error against the ideal's at the real ray's locations (value, and gradient components in raw
// mode: max and RMS), the frame's PSNR against the ideal frame's (both 8-bit), accesses and page
// faults per resample and the frame's unit time at 30 ns an access; a row "ideal" against itself.
// Then per step the patent's two data sets on four chips (docs/volume.md): 64 x 128 x 128 RGBA
// and 256 x 128 x 128 raw with gradients, rays along z one per voxel column, step 1 being "one
// resample per voxel", each through the host's slabs (x split, ghost planes) and timed as the
// slowest chip, beside the patent's 70 ms and 0.28 s. The RTL's cells and depth (Yosys, one
// netlist for every W: W is a configuration port), unless `synth` is off.
#pragma once

#include <string>

namespace tmu::texsim {

struct VolumeSweepArgs {
  std::string settings = "8,1;7,1;6,1;5,1;4,1;3,1;2,1;1,1;8,0.5;6,0.5;4,0.5;8,0.25";  // W,step
  std::string scene;     // empty: scenes/volume_marschner_lobb.json
  bool quick = false;    // a 48 x 48 frame; the patent's data sets at step 1 only
  bool synth = true;     // tmu_volume's cells and depth (scripts/synth.sh, cached)
  std::string out_dir;   // the frames per setting
  std::string markdown;  // the table; the data sets' beside it (_patent)
};

void sweep_volume(const VolumeSweepArgs& args);

}  // namespace tmu::texsim
