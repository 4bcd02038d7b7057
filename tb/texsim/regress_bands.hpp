// The bands of a regression's `render SCENE --bands N` tests joined into the whole frame
// (render::merge_bands, as `texsim merge` does) once every band passed: OUT/renders/GROUP.png.
#pragma once

#include <string>
#include <vector>

#include "texsim/regress_run.hpp"

namespace tmu::texsim {

struct BandMerge {
  std::string group;
  std::string image;  // the whole frame, when merged
  std::string error;  // why not: a band failed, or the bands do not make one frame
  bool merged() const { return error.empty(); }
};

std::vector<BandMerge> merge_band_groups(const RegressOptions& options,
                                         const std::vector<RegressResult>& results);

}  // namespace tmu::texsim
