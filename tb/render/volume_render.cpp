#include "render/volume_render.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <ostream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/image_file.hpp"
#include "volume/volume_data.hpp"
#include "volume/volume_scene.hpp"

namespace tmu::render {
namespace {

uint8_t level_of(double v) {
  return static_cast<uint8_t>(std::clamp(std::floor(255 * v + 0.5), 0.0, 255.0));
}

// A "hot" ramp for the error map: black, red, yellow, white as t goes 0 -> 1.
Rgb8 hot_colour(double t) {
  const auto c = [](double v) { return level_of(std::clamp(v, 0.0, 1.0)); };
  return {c(3 * t), c(3 * t - 1), c(3 * t - 2)};
}

std::string describe_data(const host::VolumeScene& s) {
  const auto& d = s.data;
  const std::string size = fmt::format("{} x {} x {}", d.size[0], d.size[1], d.size[2]);
  switch (d.field) {
    case host::VolumeData::Field::kMarschnerLobb:
      return fmt::format("marschner_lobb {} (f_M {}, alpha {})", size, d.marschner_lobb.f_m,
                         d.marschner_lobb.alpha);
    case host::VolumeData::Field::kSphere:
      return fmt::format("sphere {} (radius {}, slope {})", size, d.radius, d.slope);
    case host::VolumeData::Field::kEngine:
      return fmt::format("engine {} (seed {})", size, d.seed);
    case host::VolumeData::Field::kFile:
      return fmt::format("{} {}", d.file, size);
  }
  return size;
}

void write_volume_exr(const std::string& path, const VolumeFrame& f) {
  std::vector<float> px;
  px.reserve(f.pixels.size() * 3);
  for (const glm::dvec3& p : f.pixels) {
    for (int c = 0; c < 3; ++c) px.push_back(static_cast<float>(p[c]));
  }
  ImageFileSpec spec;
  spec.width = f.width;
  spec.height = f.height;
  spec.channels = 3;
  spec.format = PixelFormat::kFloat;
  write_image_file_atomically(path, spec, px.data());
}

VolumeCheckReport check_frames(Level against, const std::vector<VolumeSample>& got,
                               const std::vector<VolumeSample>& want, const VolumeFrame& a,
                               const VolumeFrame& b) {
  VolumeCheckReport c;
  c.against = std::string(name(against));
  c.compared = std::max(got.size(), want.size());
  for (size_t i = 0; i < c.compared; ++i) {
    if (i < got.size() && i < want.size() && got[i] == want[i]) continue;
    if (c.differing++ < 5) {
      const auto text = [](const std::vector<VolumeSample>& v, size_t k) {
        return k < v.size() ? fmt::format("value {} gradient ({}, {}, {})", v[k].value,
                                          v[k].gradient.x, v[k].gradient.y, v[k].gradient.z)
                            : std::string("nothing");
      };
      c.first.push_back(
          fmt::format("resample {}: expected {}, got {}", i, text(want, i), text(got, i)));
    }
  }
  if (a.chips.size() != b.chips.size()) c.counters_match = false;
  for (size_t k = 0; k < a.chips.size() && k < b.chips.size(); ++k) {
    if (a.chips[k] == b.chips[k]) continue;
    c.counters_match = false;
    const VolumeCounters &e = b.chips[k], &g = a.chips[k];
    c.first.push_back(fmt::format(
        "chip {} (expected / got): rays {} / {}, resamples {} / {}, accesses {} / {}, bank reads "
        "{} / {}, page faults {} / {}, slow accesses {} / {}",
        k, e.rays, g.rays, e.resamples, g.resamples, e.accesses, g.accesses, e.bank_reads,
        g.bank_reads, e.page_faults, g.page_faults, e.slow_accesses, g.slow_accesses));
  }
  return c;
}

}  // namespace

ImageRgb8 volume_image(const VolumeFrame& f) {
  ImageRgb8 img(f.width, f.height);
  for (size_t i = 0; i < f.pixels.size(); ++i)
    img.pixels[i] = {level_of(f.pixels[i].r), level_of(f.pixels[i].g), level_of(f.pixels[i].b)};
  return img;
}

std::vector<HostWork> volume_host_work(const host::VolumeScene& s, int chips) {
  std::vector<HostWork> w;
  w.push_back({"ray set-up",
               "per pixel the ray's entry into and exit from the volume's box, its first location, "
               "step vector and count, quantised to VoxelPos, VoxelStep and VoxelCount (the unit "
               "is given rays)"});
  if (chips > 1) {
    w.push_back({"slabs", fmt::format("each ray's locations split by the chip whose slab owns "
                                      "them ({} chips), handed on in ray order",
                                      chips)});
  }
  if (s.format == host::VolumeFormat::kRaw) {
    w.push_back({"classification", "the transfer function at each resampled value"});
    if (!s.lights.empty()) {
      w.push_back({"shading",
                   "the scene's lights at the normal -gradient / |gradient| of each "
                   "resample (000 §13: the unit returns the gradient)"});
    }
  } else if (s.data.field != host::VolumeData::Field::kFile) {
    w.push_back({"pre-classification",
                 "every voxel through the transfer function before the volume is loaded"});
  }
  w.push_back(
      {"compositing",
       s.termination
           ? fmt::format("front-to-back alpha blending (000 §13: \"only alpha blending, done by "
                         "the host\") with early termination at opacity {:.5g}, the unit given {} "
                         "locations of a ray at a time",
                         s.termination->alpha, s.termination->segment)
           : std::string("front-to-back alpha blending (000 §13: \"only alpha blending, done by "
                         "the host\"), every location of every ray")});
  return w;
}

int render_volume(const std::string& scene_path, const RenderOptions& o, std::ostream& log,
                  VolumeReport* report_out) {
  const auto t_start = std::chrono::steady_clock::now();
  if (o.tiles > 1) throw InputError("--tile", "", "not for a volume scene");
  if (!o.save_trace.empty()) throw InputError("--save-trace", "", "not for a volume scene");
  if (!o.replay_trace.empty()) throw InputError("--replay", "", "not for a volume scene");
  if (o.inject_fault >= 0 && o.level != Level::kHls && o.level != Level::kRtl) {
    throw InputError("--inject-fault", "",
                     "a volume scene's fault goes into an hls or rtl engine's output");
  }
  if (o.waveform) throw InputError("--waveform", "", "not for a volume scene");
  const host::VolumeScene scene = host::load_volume_scene(scene_path);
  const int chips = o.chips > 0 ? o.chips : scene.chips;
  if (const std::string why =
          host::slab_problem(scene.data.size, chips, scene.slab_axis, host::volume_mode(scene));
      !why.empty()) {
    throw InputError("--chips", "", why);
  }
  const std::vector<volume::VoxelGrid> grids = host::volume_grids(scene);
  const std::vector<host::RaySetup> rays = set_up_rays(scene);

  VolumeReport rep;
  rep.scene = scene_path;
  rep.engine = std::string(name(o.level));
  rep.volume = describe_data(scene);
  rep.format = scene.format == host::VolumeFormat::kRaw ? "raw" : "rgba";
  rep.components = static_cast<int>(grids.size());
  rep.weight_bits = scene.weight_bits;
  rep.step = scene.step;
  rep.termination = scene.termination;
  rep.host_work = volume_host_work(scene, o.level == Level::kIdeal ? 1 : chips);

  std::vector<VolumeSample> record;
  VolumeCastOptions cast{o.level, chips, o.check ? &record : nullptr};
  // hls and rtl: every piece of the unit's work compared unit by unit as well.
  if (o.check && *o.check != Level::kIdeal && (o.level == Level::kHls || o.level == Level::kRtl))
    cast.check_units = *o.check;
  cast.inject_fault = o.inject_fault;
  const VolumeFrame frame = cast_volume(scene, grids, rays, cast);
  rep.frame = frame;
  rep.frame.pixels.clear();

  std::filesystem::create_directories(o.out_dir);
  const std::filesystem::path dir(o.out_dir);
  const ImageRgb8 image = volume_image(frame);
  const std::string png = (dir / "render.png").string();
  write_image(png, image);
  rep.files.push_back(png);
  if (o.level == Level::kIdeal) {
    const std::string exr = (dir / "render.exr").string();
    write_volume_exr(exr, frame);
    rep.files.push_back(exr);
  }

  if (o.check) {
    std::vector<VolumeSample> expected;
    const VolumeFrame ref = cast_volume(scene, grids, rays, {*o.check, chips, &expected});
    rep.check = check_frames(*o.check, record, expected, frame, ref);
    rep.check->units = frame.unit_check;
  }

  if (o.compare_ideal && o.level != Level::kIdeal) {
    const VolumeFrame ideal = cast_volume(scene, grids, rays, {Level::kIdeal, 1, nullptr});
    CompareReport c;
    ImageRgb8 heat(frame.width, frame.height);
    double se = 0, sum = 0;
    for (size_t i = 0; i < ideal.pixels.size(); ++i) {
      const Rgb8 g = image.pixels[i];
      const double got[3] = {double(g.r), double(g.g), double(g.b)};
      double worst = 0;
      for (int ch = 0; ch < 3; ++ch) {
        const double e = got[ch] - 255 * std::clamp(ideal.pixels[i][ch], 0.0, 1.0);
        se += e * e;
        sum += std::abs(e);
        worst = std::max(worst, std::abs(e));
      }
      c.max_error = std::max(c.max_error, worst);
      heat.pixels[i] = hot_colour(worst / 4.0);
    }
    const double n = 3.0 * static_cast<double>(std::max<size_t>(ideal.pixels.size(), 1));
    c.psnr = se > 0 ? 10 * std::log10(255.0 * 255.0 * n / se) : INFINITY;
    c.mean_error = sum / n;
    const std::string err = (dir / "render.compare-error.png").string();
    write_image(err, heat);
    rep.files.push_back(err);
    rep.compare = c;
  }

  rep.total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  const std::string json_path = (dir / "render.report.json").string();
  const std::string text_path = (dir / "render.report.txt").string();
  rep.files.push_back(json_path);
  rep.files.push_back(text_path);
  write_file_atomically(json_path, rep.json());
  const std::string text = rep.text();
  write_file_atomically(text_path, text);
  log << text;
  if (report_out) *report_out = rep;
  return rep.check && !rep.check->match() ? 1 : 0;
}

}  // namespace tmu::render
