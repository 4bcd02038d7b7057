// `texsim sweep footprint`: what footprint assembly (000 §10) buys in quality and what it
// costs. One scene's fragments (default scenes/grazing.json, a floor and a wall seen at grazing
// angles) through isotropic trilinear, the golden footprint unit at N max = 2, 4, 8, 16, the
// ideal footprint unit marching along the ellipse axis and along the longer side, and
// OpenImageIO's anisotropic filter; each against a supersampled reference: PSNR, errors,
// probes and predicted cycles per pixel, wall time. docs/sweeps/footprint.md.
#pragma once

#include <string>

namespace tmu::texsim {

struct FootprintSweepArgs {
  std::string scene;     // empty: scenes/grazing.json of the source tree
  int k = 0;             // reference sub-pixels per side; 0: 8 (4 with quick)
  bool quick = false;    // half the frame (and k 4): for tests
  std::string out_dir;   // images and error maps, when set
  std::string markdown;  // the table as Markdown, when set
};

void sweep_footprint(const FootprintSweepArgs& args);

}  // namespace tmu::texsim
