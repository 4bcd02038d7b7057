#include "render/render.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <ostream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/image_file.hpp"
#include "geometry/mesh.hpp"
#include "harness/waveform.hpp"
#include "raster/rasterizer.hpp"
#include "render/chip_stage.hpp"
#include "render/pipeline.hpp"
#include "render/progress.hpp"
#include "render/unit_check.hpp"
#include "scene/scene.hpp"
#include "texram/sampler_config.hpp"
#include "trace/fragment_trace.hpp"

namespace tmu::render {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

Rgb8 rgb_of(uint32_t rgba) {
  return {static_cast<uint8_t>(rgba >> 24), static_cast<uint8_t>(rgba >> 16),
          static_cast<uint8_t>(rgba >> 8)};
}

// The frame band with the background and every fragment's colour.
ImageRgb8 compose(const host::Scene& scene, const Band& band,
                  const std::vector<host::FragmentRecord>& records,
                  const std::vector<uint32_t>& rgba) {
  ImageRgb8 img(band.frame_width, band.row_end - band.row_begin);
  const Rgb8 bg = rgb_of(texram::rgba(
      static_cast<uint32_t>(std::lround(std::clamp(scene.background.r, 0.0, 1.0) * 255)),
      static_cast<uint32_t>(std::lround(std::clamp(scene.background.g, 0.0, 1.0) * 255)),
      static_cast<uint32_t>(std::lround(std::clamp(scene.background.b, 0.0, 1.0) * 255)), 255));
  std::fill(img.pixels.begin(), img.pixels.end(), bg);
  for (size_t i = 0; i < records.size(); ++i)
    img.at(records[i].x, records[i].y - band.row_begin) = rgb_of(rgba[i]);
  return img;
}

// A "hot" colour ramp for error maps: black, red, yellow, white as t goes 0 -> 1.
Rgb8 hot(double t) {
  auto c = [](double v) {
    return static_cast<uint8_t>(std::lround(255 * std::clamp(v, 0.0, 1.0)));
  };
  return {c(3 * t), c(3 * t - 1), c(3 * t - 2)};
}

std::string describe(const host::FragmentRecord& r, const host::Scene& scene) {
  return fmt::format("material {} u={:.4f} v={:.4f} lambda={:.4f} shade=0x{:08X}",
                     scene.materials[r.material].name, r.u / 256.0, r.v / 256.0, r.lambda / 256.0,
                     r.shade);
}

// The ideal engine's colours as a float image (EXR): what 8 bits cannot hold.
void write_exr(const std::string& path, const Band& band, const host::Scene& scene,
               const std::vector<host::FragmentRecord>& records,
               const std::vector<glm::dvec4>& ideal) {
  std::vector<float> px(static_cast<size_t>(band.frame_width) * (band.row_end - band.row_begin) *
                        3);
  for (size_t i = 0; i < px.size(); i += 3) {
    px[i] = static_cast<float>(scene.background.r);
    px[i + 1] = static_cast<float>(scene.background.g);
    px[i + 2] = static_cast<float>(scene.background.b);
  }
  for (size_t k = 0; k < records.size(); ++k) {
    const size_t at =
        3 * (static_cast<size_t>(records[k].y - band.row_begin) * band.frame_width + records[k].x);
    for (int c = 0; c < 3; ++c)
      px[at + static_cast<size_t>(c)] = static_cast<float>(ideal[k][c] / 255.0);
  }
  ImageFileSpec spec;
  spec.width = band.frame_width;
  spec.height = band.row_end - band.row_begin;
  spec.channels = 3;
  spec.format = PixelFormat::kFloat;
  write_image_file_atomically(path, spec, px.data());
}

}  // namespace

int render_scene(const std::string& scene_path, const RenderOptions& o, std::ostream& log,
                 RenderReport* report_out) {
  const auto t_start = Clock::now();
  const host::Scene scene = host::load_scene(scene_path);
  const int width = scene.camera.width, height = scene.camera.height;
  if (o.tiles > height)
    throw InputError("--tile", "", fmt::format("{} bands for a frame of {} rows", o.tiles, height));
  RenderReport rep;
  rep.scene = scene_path;
  rep.engine = std::string(name(o.level));
  rep.band = band_of(o.tile, o.tiles, width, height);
  const Band& band = rep.band;
  rep.pixels = static_cast<uint64_t>(width) * static_cast<uint64_t>(band.row_end - band.row_begin);

  auto t = Clock::now();
  Pipeline pipe(scene, o.level, o.chips, o.video.get());
  pipe.set_jobs(o.jobs);
  rep.textures_s = since(t);
  if (const ChipStage* chips = pipe.chips()) rep.chips = chip_lines(scene, *chips);

  // The fragments: from the front end, or replayed from a trace.
  t = Clock::now();
  std::vector<host::Fragment> fragments;
  std::vector<host::FragmentRecord> records;
  if (!o.replay_trace.empty()) {
    if (o.level == Level::kIdeal || o.compare_ideal) {
      throw InputError("--replay", "",
                       "a trace holds fixed-point records; the ideal engine needs the front end");
    }
    const host::FragmentTrace trace = host::read_trace(o.replay_trace);
    if (trace.width != width || trace.height != height) {
      throw InputError(o.replay_trace, "frame",
                       fmt::format("the trace is {}x{}, the scene {}x{}", trace.width, trace.height,
                                   width, height));
    }
    for (const host::FragmentRecord& r : trace.records) {
      if (r.y >= band.row_begin && r.y < band.row_end) records.push_back(r);
      if (r.material >= scene.materials.size()) {
        throw InputError(o.replay_trace, "material",
                         fmt::format("material {} is not in the scene", r.material));
      }
    }
    rep.raster.fragments = rep.raster.visible = records.size();
  } else {
    fragments = front_end(scene, pipe, band.row_begin, band.row_end, &rep.raster);
    for (const host::Fragment& f : fragments) records.push_back(host::quantize(f));
  }
  rep.front_end_s = since(t);
  std::filesystem::create_directories(o.out_dir);
  const std::filesystem::path dir(o.out_dir);
  if (!o.save_trace.empty()) {
    host::write_trace(o.save_trace, {scene_path, width, height, records});
    rep.files.push_back(o.save_trace);
  }

  // Texturing.
  t = Clock::now();
  std::vector<uint32_t> rgba;
  std::vector<glm::dvec4> ideal;
  {
    ProgressBar bar(fmt::format("render {}", name(o.level)), "frag", o.progress);
    rgba = pipe.shade(records, &fragments, o.level == Level::kIdeal ? &ideal : nullptr,
                      [&](uint64_t done, uint64_t total) { bar.update(done, total); });
  }
  rep.units_s = since(t);
  if (o.inject_fault >= 0 && static_cast<size_t>(o.inject_fault) < rgba.size()) {
    rgba[static_cast<size_t>(o.inject_fault)] ^= 0x100u;  // a deliberate wrong bit (blue LSB)
  }
  if (o.level != Level::kIdeal) rep.host_work = pipe.host_work();
  for (const UnitRun& u : pipe.units()) {
    UnitReport ur{u.name(),         u.kind, static_cast<uint64_t>(u.result.outputs.size()),
                  u.result.cycles,  false,  u.result.seconds,
                  u.result.counters};
    ur.cycles = unit_cycles(u, &ur.predicted);
    rep.units.push_back(std::move(ur));
  }

  // The picture.
  const ImageRgb8 image = compose(scene, band, records, rgba);
  const std::string stem = o.stem.empty() ? band_stem(o.tile, o.tiles) : o.stem;
  const std::string png = (dir / (stem + ".png")).string();
  if (o.tiles > 1) {
    write_band(png, image, band);
  } else {
    write_image(png, image);
  }
  rep.files.push_back(png);
  if (o.level == Level::kIdeal) {
    const std::string exr = (dir / (stem + ".exr")).string();
    write_exr(exr, band, scene, records, ideal);
    rep.files.push_back(exr);
  }

  // Bit for bit against another engine, fragment by fragment.
  if (o.check) {
    Pipeline ref(scene, *o.check, o.chips, o.video.get());
    ref.set_jobs(o.jobs);
    // Its own vertex units, for the unit check (the pixels compare on this run's fragments).
    if (samples_at_vertices_anywhere(scene))
      front_end(scene, ref, band.row_begin, band.row_end, nullptr);
    const std::vector<uint32_t> expected = ref.shade(records, &fragments, nullptr);
    CheckReport c;
    c.against = std::string(name(*o.check));
    c.compared = records.size();
    ImageRgb8 heat = compose(scene, band, records, expected);
    for (Rgb8& p : heat.pixels)
      p = {static_cast<uint8_t>(p.r / 4), static_cast<uint8_t>(p.g / 4),
           static_cast<uint8_t>(p.b / 4)};
    size_t first = records.size();
    for (size_t i = 0; i < records.size(); ++i) {
      if (rgba[i] == expected[i]) continue;
      if (c.differing++ == 0) first = i;
      if (c.first.size() < 5)
        c.first.push_back(
            {records[i].x, records[i].y, describe(records[i], scene), expected[i], rgba[i]});
      int worst = 0;
      for (int ch = 0; ch < 4; ++ch) {
        worst = std::max(worst, std::abs(static_cast<int>(texram::channel(rgba[i], ch)) -
                                         static_cast<int>(texram::channel(expected[i], ch))));
      }
      heat.at(records[i].x, records[i].y - band.row_begin) = hot(0.34 + worst / 48.0);
    }
    const UnitCheck units = check_units(pipe.units(), ref.units());
    c.units_compared = units.compared;
    c.unit_differences = units.differences;
    if (c.differing) {
      const std::string diff = (dir / (stem + ".check-diff.png")).string();
      write_image(diff, heat);
      rep.files.push_back(diff);
    }
    if (!c.match() && o.waveform && o.level == Level::kRtl) {
      // The unit behind the first mismatch: the first unit whose outputs, requests or counters
      // differ from the reference's same unit; else (a difference after the units) the unit
      // that made the first differing fragment's last output.
      std::optional<std::pair<size_t, uint64_t>> culprit;  // unit, cycle
      if (units.first_unit) culprit = {*units.first_unit, units.first_cycle};
      for (size_t u = pipe.units().size(); u-- > 0 && !culprit && c.differing;) {
        const auto& outs = pipe.fragments_of_outputs()[u];
        const auto it = std::find(outs.begin(), outs.end(), first);
        if (it != outs.end())
          culprit = {u,
                     pipe.units()[u].result.output_cycles[static_cast<size_t>(it - outs.begin())]};
      }
      if (culprit) {
        UnitRun& unit = pipe.units()[culprit->first];
        const tb::WaveWindow w =
            tb::dump_waveform(*unit.engine("rtl"), unit.items, tb::RunOptions{}, culprit->second,
                              64, 16, o.out_dir, stem + ".mismatch", unit.block->ports());
        c.waveform = fmt::format("{} (unit {}, cycles {}..{}; gtkwave {})", w.fst, unit.name(),
                                 w.begin, w.end, w.gtkw);
        rep.files.push_back(w.fst);
      }
    }
    rep.check = c;
  }

  // Against the ideal model: how far the hardware's arithmetic is from exact.
  if (o.compare_ideal && o.level != Level::kIdeal) {
    Pipeline ip(scene, Level::kIdeal);
    std::vector<glm::dvec4> exact;
    // Orders texture and composed: the ideal's own vertex colours, interpolated.
    const std::vector<host::Fragment> ideal_fragments =
        samples_at_vertices_anywhere(scene)
            ? front_end(scene, ip, band.row_begin, band.row_end, nullptr)
            : fragments;
    ip.shade(records, &ideal_fragments, &exact);
    CompareReport c;
    ImageRgb8 heat(width, band.row_end - band.row_begin);
    double se = 0, sum = 0;
    for (size_t i = 0; i < records.size(); ++i) {
      double worst = 0;
      for (int ch = 0; ch < 3; ++ch) {
        const double e = texram::channel(rgba[i], ch) - exact[i][ch];
        se += e * e;
        sum += std::abs(e);
        worst = std::max(worst, std::abs(e));
      }
      c.max_error = std::max(c.max_error, worst);
      heat.at(records[i].x, records[i].y - band.row_begin) = hot(worst / 4.0);
    }
    const double n = 3.0 * static_cast<double>(std::max<size_t>(records.size(), 1));
    c.psnr = se > 0 ? 10 * std::log10(255.0 * 255.0 * n / se) : INFINITY;
    c.mean_error = sum / n;
    const std::string err = (dir / (stem + ".compare-error.png")).string();
    write_image(err, heat);
    rep.files.push_back(err);
    rep.compare = c;
  }

  rep.total_s = since(t_start);
  const std::string json_path = (dir / (stem + ".report.json")).string();
  const std::string text_path = (dir / (stem + ".report.txt")).string();
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
