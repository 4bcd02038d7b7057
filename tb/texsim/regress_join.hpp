// The tests of one list line put together once every one of them passed: the bands of a
// `render SCENE --bands N` into the whole frame (render::merge_bands, as `texsim merge` does),
// OUT/renders/GROUP.png; the frame ranges of a `render FLYOVER --frames-per-test K` into one
// folder of the fly-over's frames, OUT/renders/GROUP/.
#pragma once

#include <string>
#include <vector>

#include "texsim/regress_run.hpp"

namespace tmu::texsim {

struct GroupJoin {
  std::string group;
  Join join = Join::kNone;
  std::string output;  // the whole frame or the folder of frames, when joined
  size_t frames = 0;   // the frames gathered
  std::string error;   // why not: a test failed, or the bands do not make one frame
  bool joined() const { return error.empty(); }
  std::string summary() const;  // a line for the regression's summary
};

std::vector<GroupJoin> join_groups(const RegressOptions& options,
                                   const std::vector<RegressResult>& results);

}  // namespace tmu::texsim
