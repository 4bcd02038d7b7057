// `texsim render`: a scene through the host front end and the texture pipeline it calls for,
// at one model level; the picture, a report, and on request the bit-exact check against
// another engine, the comparison with the ideal model, a fragment trace, one band of the frame.
#pragma once

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

#include "render/report.hpp"
#include "render/units.hpp"
#include "render/video_feed.hpp"

namespace tmu::render {

struct RenderOptions {
  Level level = Level::kGolden;
  std::string out_dir = "out";
  int tile = 0, tiles = 1;     // render band `tile` of `tiles`
  std::optional<Level> check;  // compare every fragment's result with this engine
  bool compare_ideal = false;  // PSNR and error map of the image against the ideal engine's
  bool waveform = false;       // with check and rtl: FST window around the first mismatch
  bool progress = true;        // a progress bar on a terminal
  std::string save_trace;      // write the fragment records here
  std::string replay_trace;    // take the fragment records from here instead of the front end
  int inject_fault = -1;       // flip a bit of this fragment's result (proves --check catches it)
  int chips = 0;  // TEXRAM chips: a surface scene's maps through them (render/chip_stage),
                  // a volume scene's slabs over them; 0: none, the volume's own key
  int jobs = 1;   // materials shaded at once (Pipeline::set_jobs)
  // A video scene's frame (render/video_render): every video map's buffers as the frame sees
  // them, and the files' stem ("video.frame-0003"; "" for render or the band's).
  std::shared_ptr<const VideoState> video;
  std::string stem;
};

// Renders; prints the text report to `log` and writes the files into out_dir. Returns the exit
// code: 0 done (and matched, when checked), 1 a mismatch. Throws InputError on bad input.
int render_scene(const std::string& scene_path, const RenderOptions& options, std::ostream& log,
                 RenderReport* report = nullptr);

}  // namespace tmu::render
