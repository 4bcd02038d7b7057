// The report of a volume render (`texsim render` of a volume scene): the volume and the unit's
// mode, the chips and their slabs, the rays and their locations (set up, resampled, composited:
// what early termination saved), the unit's memory (accesses, page faults, accesses per resample,
// the time at 30 ns an access, chip by chip), the host's work, and the verdicts. Written as text
// (printed and saved) and JSON, like every render's report (render/report.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/report.hpp"
#include "render/volume_cast.hpp"

namespace tmu::render {

struct VolumeCheckReport {
  std::string against;
  uint64_t compared = 0, differing = 0;  // resamples
  bool counters_match = true;
  std::vector<std::string> first;  // the first differences, readable
  // hls, rtl: the unit-by-unit comparison of every piece (render/volume_engine_block.hpp).
  std::optional<VolumePieceCheck> units;
  bool match() const { return differing == 0 && counters_match && (!units || units->match()); }
};

struct VolumeReport {
  std::string scene, engine;
  std::string volume;  // what the data is, e.g. "marschner_lobb 64 x 64 x 64"
  std::string format;  // "raw" | "rgba"
  int components = 1, weight_bits = 8;
  double step = 1;
  std::optional<host::Termination> termination;
  VolumeFrame frame;  // its counts (its pixels are not reported)
  std::vector<HostWork> host_work;
  double total_s = 0;
  std::optional<VolumeCheckReport> check;
  std::optional<CompareReport> compare;
  std::vector<std::string> files;

  std::string text() const;
  std::string json() const;
};

}  // namespace tmu::render
