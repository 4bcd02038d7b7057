// A regression list (`texsim regress LIST`, docs/regress.md): what to run, one line a test
// family, expanded into single tests that each are one texsim command.
//
//   # comment
//   cosim BLOCK [--seeds A..B] [cosim options...]   one test per seed (default --seeds 1..1)
//   render SCENE [render options...]                one test (SCENE relative to the list's folder)
//   render SCENE --bands N [render options...]      N tests, band i of N each (--tile i/N),
//                                                   joined into one image when all passed
//   render FLYOVER --frames-per-test K [--frames A-B] [options...]
//                                                   one test per K frames of the fly-over's
//                                                   path (or of A-B), each --frames a-b; their
//                                                   frames gathered into one folder when all passed
//
// Every option is passed to texsim as written; the runner adds only where the test's outputs
// go (--wave-dir, --out), so a failure's command line reproduces it.
#pragma once

#include <string>
#include <vector>

namespace tmu::texsim {

// How the tests of one list line are put together when every one of them passed.
enum class Join {
  kNone,
  kBands,   // the bands of a frame into one image
  kFrames,  // the frame ranges of a fly-over into one folder of frames
};

struct RegressTest {
  std::string name;               // unique: "cosim.trilinear.seed3", "render.default.2"
  std::vector<std::string> args;  // texsim's arguments, without the outputs' places
  std::string kind;               // "cosim" or "render"
  std::string group;              // the line's name when its tests are joined; else ""
  Join join = Join::kNone;
};

// Throws InputError(path, "line N", reason): an unknown command, a missing block or scene, a
// malformed or empty seed range, a band count outside 1..256, --tile with --bands, a test name
// twice, --frames-per-test on a scene that is not a fly-over or with --bands, a frame range
// outside the path.
std::vector<RegressTest> read_regress_list(const std::string& path);

}  // namespace tmu::texsim
