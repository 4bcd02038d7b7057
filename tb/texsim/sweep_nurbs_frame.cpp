#include "texsim/sweep_nurbs_frame.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "geometry/mesh.hpp"
#include "raster/fragment.hpp"
#include "raster/rasterizer.hpp"
#include "render/pipeline.hpp"
#include "render/unit_check.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::texsim {
namespace {

using Clock = std::chrono::steady_clock;

// What render_scene reports: each unit's cycles, predicted for untimed golden units.
uint64_t unit_cycles(const std::vector<render::UnitRun>& units) {
  uint64_t n = 0;
  for (const render::UnitRun& u : units) n += render::unit_cycles(u);
  return n;
}

}  // namespace

NurbsFrame render_frame(const host::Scene& scene, render::Level level,
                        std::optional<render::Level> check) {
  NurbsFrame frame;
  frame.width = scene.camera.width;
  frame.height = scene.camera.height;
  const size_t pixels = static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height);
  frame.covered.assign(pixels, 0);
  frame.colour.assign(pixels, glm::dvec3(0));

  // render::front_end's steps, timed apart: the vertex colours (orders texture and composed)
  // are the units' work, not the front end's.
  render::Pipeline pipe(scene, level);
  auto t = Clock::now();
  std::vector<host::Mesh> meshes = host::make_meshes(scene, pipe.texture_sizes());
  double seconds = std::chrono::duration<double>(Clock::now() - t).count();
  pipe.colour_vertices(meshes);
  t = Clock::now();
  const std::vector<host::Fragment> fragments =
      host::rasterize(scene, meshes, pipe.uv_scales(), 0, -1, nullptr);
  frame.front_end_s = seconds + std::chrono::duration<double>(Clock::now() - t).count();
  for (const host::Mesh& m : meshes) frame.triangles += m.triangles.size();

  std::vector<host::FragmentRecord> records;
  records.reserve(fragments.size());
  for (const host::Fragment& f : fragments) records.push_back(host::quantize(f));
  std::vector<glm::dvec4> ideal;
  const std::vector<uint32_t> rgba =
      pipe.shade(records, &fragments, level == render::Level::kIdeal ? &ideal : nullptr, nullptr);
  for (size_t i = 0; i < records.size(); ++i) {
    const size_t at =
        static_cast<size_t>(records[i].y) * static_cast<size_t>(frame.width) + records[i].x;
    frame.covered[at] = 1;
    frame.colour[at] = level == render::Level::kIdeal
                           ? glm::dvec3(ideal[i])
                           : glm::dvec3(texram::channel(rgba[i], 0), texram::channel(rgba[i], 1),
                                        texram::channel(rgba[i], 2));
  }
  if (level != render::Level::kIdeal) frame.unit_cycles = unit_cycles(pipe.units());

  if (check) {
    render::Pipeline ref(scene, *check);
    // Its own vertex units, for the unit check; the pixels compare on this run's fragments.
    if (render::samples_at_vertices_anywhere(scene)) render::front_end(scene, ref, 0, -1, nullptr);
    const std::vector<uint32_t> expected = ref.shade(records, &fragments, nullptr, nullptr);
    frame.equals_check = expected == rgba && render::check_units(pipe.units(), ref.units()).match();
  }
  return frame;
}

NurbsFrameError frame_error(const NurbsFrame& got, const NurbsFrame& reference) {
  NurbsFrameError e;
  double se = 0, sum = 0;
  for (size_t i = 0; i < got.covered.size(); ++i) {
    if (got.covered[i] != reference.covered[i]) ++e.coverage_diff;
    if (!got.covered[i] || !reference.covered[i]) continue;
    ++e.compared;
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(got.colour[i][c] - reference.colour[i][c]);
      se += d * d;
      sum += d;
      e.max = std::max(e.max, d);
    }
  }
  const double n = 3.0 * static_cast<double>(std::max<uint64_t>(e.compared, 1));
  e.psnr = se > 0 ? 10 * std::log10(255.0 * 255.0 * n / se) : INFINITY;
  e.mean = sum / n;
  return e;
}

}  // namespace tmu::texsim
