#include "render/bands.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <ostream>
#include <sstream>

#include "common/error.hpp"
#include "render/jobs.hpp"
#include "render/tiles.hpp"
#include "scene/scene.hpp"

namespace tmu::render {

int render_bands(const std::string& scene_path, const RenderOptions& options, int bands,
                 std::ostream& log, std::vector<RenderReport>* reports) {
  if (options.tiles != 1) throw InputError("--bands", "", "not with --tile (each band is a tile)");
  if (!options.save_trace.empty() || !options.replay_trace.empty()) {
    throw InputError("--bands", "", "not with --save-trace or --replay (a trace is one frame's)");
  }
  // The bad inputs every band would meet, once and before any band starts (a scene error would
  // otherwise come from every thread).
  const host::Scene scene = host::load_scene(scene_path);
  if (bands < 1 || bands > scene.camera.height) {
    throw InputError("--bands", "",
                     fmt::format("{} bands for a frame of {} rows", bands, scene.camera.height));
  }
  const auto count = static_cast<size_t>(bands);
  std::vector<int> codes(count, 0);
  std::vector<std::string> logs(count);
  std::vector<RenderReport> reps(count);
  const int jobs = options.level == Level::kHls ? 1 : options.jobs;
  run_jobs(count, jobs, [&](size_t i) {
    RenderOptions o = options;
    o.tile = static_cast<int>(i);
    o.tiles = bands;
    o.jobs = 1;  // the threads are the bands'
    o.progress = false;
    std::ostringstream text;
    codes[i] = render_scene(scene_path, o, text, &reps[i]);
    logs[i] = text.str();
  });
  int code = 0;
  std::vector<std::string> pngs;
  for (size_t i = 0; i < count; ++i) {
    log << fmt::format("=== band {} of {}\n", i, bands) << logs[i];
    code = std::max(code, codes[i]);
    pngs.push_back(
        (std::filesystem::path(options.out_dir) / (band_stem(static_cast<int>(i), bands) + ".png"))
            .string());
  }
  if (code == 0) {
    const std::string whole = (std::filesystem::path(options.out_dir) / "render.png").string();
    write_image(whole, merge_bands(pngs));
    log << fmt::format("{} bands joined: {}\n", bands, whole);
  } else {
    log << fmt::format("{} bands not joined: a band's check found a mismatch\n", bands);
  }
  if (reports) *reports = std::move(reps);
  return code;
}

}  // namespace tmu::render
