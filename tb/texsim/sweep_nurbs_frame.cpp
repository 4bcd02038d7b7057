#include "texsim/sweep_nurbs_frame.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "geometry/mesh.hpp"
#include "nurbs/ray_hit.hpp"
#include "raster/fragment.hpp"
#include "raster/rasterizer.hpp"
#include "raster/shading.hpp"
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

// Moves the fragments of NURBS objects whose (s, t) reach the units unmapped onto the surface.
void move_onto_surface(const host::Scene& scene, const std::vector<glm::ivec2>& uv_scales,
                       std::vector<host::Fragment>& fragments, uint64_t& moved, uint64_t& kept) {
  for (host::Fragment& f : fragments) {
    const host::Object& object = scene.objects[static_cast<size_t>(f.object)];
    const host::Material& material = scene.materials[static_cast<size_t>(f.material)];
    if (object.shape != host::Object::Shape::kNurbs ||
        (material.tau && material.order != host::Material::Order::kPc))
      continue;
    const glm::dvec2 scale(uv_scales[static_cast<size_t>(f.material)]);
    const std::optional<host::nurbs::PixelHit> hit =
        host::nurbs::hit_through_pixel(object, scene.camera, f.x + 0.5, f.y + 0.5, f.uv / scale);
    if (!hit) {
      ++kept;
      continue;
    }
    ++moved;
    f.uv = hit->pc * scale;
    f.r1 = hit->d_dx * scale;
    f.r2 = hit->d_dy * scale;
    if (material.lod == host::Material::Lod::kPixel)
      f.lambda = std::log2(std::max({glm::length(f.r1), glm::length(f.r2), host::kMinFootprint}));
    // The tessellation's normals face the way the surface's do; keep the side it shows.
    f.normal = glm::dot(hit->normal, f.normal) < 0 ? -hit->normal : hit->normal;
    f.view = glm::normalize(scene.camera.position - hit->position);
    f.shade = host::shade(scene.lights, f.normal, hit->position);
  }
}

NurbsFrame empty_frame(const host::Scene& scene) {
  NurbsFrame frame;
  frame.width = scene.camera.width;
  frame.height = scene.camera.height;
  const size_t pixels = static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height);
  frame.covered.assign(pixels, 0);
  frame.colour.assign(pixels, glm::dvec3(0));
  return frame;
}

// render::front_end's steps, timed apart: the vertex colours (orders texture and composed) are
// the units' work, not the front end's.
std::vector<host::Fragment> front_end(const host::Scene& scene, render::Pipeline& pipe,
                                      NurbsFrame& frame) {
  auto t = Clock::now();
  std::vector<host::Mesh> meshes = host::make_meshes(scene, pipe.texture_sizes());
  double seconds = std::chrono::duration<double>(Clock::now() - t).count();
  pipe.colour_vertices(meshes);
  t = Clock::now();
  std::vector<host::Fragment> fragments =
      host::rasterize(scene, meshes, pipe.uv_scales(), 0, -1, nullptr);
  frame.front_end_s = seconds + std::chrono::duration<double>(Clock::now() - t).count();
  for (const host::Mesh& m : meshes) frame.triangles += m.triangles.size();
  return fragments;
}

std::vector<host::FragmentRecord> records_of(const std::vector<host::Fragment>& fragments) {
  std::vector<host::FragmentRecord> records;
  records.reserve(fragments.size());
  for (const host::Fragment& f : fragments) records.push_back(host::quantize(f));
  return records;
}

// Shades `fragments` through `pipe` into `frame`'s pixels; returns the 8-bit colours.
std::vector<uint32_t> shade(render::Pipeline& pipe, render::Level level,
                            const std::vector<host::Fragment>& fragments,
                            const std::vector<host::FragmentRecord>& records, NurbsFrame& frame) {
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
  return rgba;
}

}  // namespace

NurbsFrame render_frame(const host::Scene& scene, render::Level level,
                        std::optional<render::Level> check) {
  render::Pipeline pipe(scene, level);
  NurbsFrame frame = empty_frame(scene);
  const std::vector<host::Fragment> fragments = front_end(scene, pipe, frame);
  const std::vector<host::FragmentRecord> records = records_of(fragments);
  const std::vector<uint32_t> rgba = shade(pipe, level, fragments, records, frame);
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

NurbsFrame reference_render(const host::Scene& scene, ReferenceStats* stats) {
  render::Pipeline pipe(scene, render::Level::kIdeal);
  NurbsFrame frame = empty_frame(scene);
  std::vector<host::Fragment> fragments = front_end(scene, pipe, frame);
  NurbsFrame tessellated = frame;
  shade(pipe, render::Level::kIdeal, fragments, records_of(fragments), tessellated);
  ReferenceStats r;
  move_onto_surface(scene, pipe.uv_scales(), fragments, r.moved, r.kept);
  shade(pipe, render::Level::kIdeal, fragments, records_of(fragments), frame);
  r.tessellation_error = frame_error(tessellated, frame);
  if (stats) *stats = r;
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
