// `texsim sweep clipmap`: the clip-map (003) per tile size and substitution rule on the
// fly-over (scenes/flyover.json, its terrain at 2^V texels, V = 10 by default so that the same
// frames can be rendered from the whole pyramid): texels resident against the whole mipmap,
// texels loaded per frame, the share of wayward samples, and the frames' error against the same
// frames with every level resident; texels loaded per frame against the camera's speed; the
// unit's hardware at the default (rtl = golden, cycles per frame and per sample, cells); and
// the patent's configuration (32k, 1k tiles) by formula beside its figures (docs/clipmap.md).
#pragma once

#include <string>

namespace tmu::texsim {

struct ClipmapSweepArgs {
  std::string settings = "4;5;6;7;8";  // log2 tile sides
  int log2_virtual = 10;  // the terrain's side; up to 10 the whole pyramid is a reference
  std::string scene;      // default scenes/flyover.json
  std::string work_dir;   // where the terrain and the frames go (default a temporary)
  bool synth = true;
  std::string markdown;  // the tile table; _speed and _hardware beside it
};

void sweep_clipmap(const ClipmapSweepArgs& args);

}  // namespace tmu::texsim
