#include "texsim/sweep_volume.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>

#include "common/error.hpp"
#include "common/image.hpp"
#include "render/volume_cast.hpp"
#include "render/volume_render.hpp"
#include "texsim/sweep_support.hpp"
#include "volume/volume_data.hpp"

namespace tmu::texsim {
namespace {

using render::Level;
using render::VolumeFrame;
using render::VolumeSample;

struct Setting {
  int weight_bits = 8;
  double step = 1;
  std::string name;
};

std::vector<Setting> parse_volume_settings(const std::string& text) {
  std::vector<Setting> out;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ';');) {
    Setting s;
    char comma = 0;
    std::stringstream one(item);
    if (!(one >> s.weight_bits >> comma >> s.step) || comma != ',' || !(one >> std::ws).eof())
      throw InputError("--settings", item, "expected W,step (weight bits, step in voxels)");
    if (s.weight_bits < 1 || s.weight_bits > 8)
      throw InputError("--settings", item, "W is 1..8 weight bits");
    if (!(s.step >= host::kMinStep && s.step <= host::kMaxStep))
      throw InputError("--settings", item,
                       fmt::format("the step is {}..{} voxels", host::kMinStep, host::kMaxStep));
    s.name = fmt::format("{},{}", s.weight_bits, s.step);
    out.push_back(s);
  }
  if (out.empty()) throw InputError("--settings", "", "no setting given");
  return out;
}

struct Render {
  VolumeFrame frame;
  std::vector<VolumeSample> samples;  // every resample, in the unit's order
  ImageRgb8 image;
};

Render render_at(const host::VolumeScene& scene, const std::vector<volume::VoxelGrid>& grids,
                 Level level) {
  Render r;
  r.frame = render::cast_volume(scene, grids, render::set_up_rays(scene), {level, 1, &r.samples});
  r.image = render::volume_image(r.frame);
  return r;
}

struct Errors {
  double value_max = 0, value_rms = 0, grad_max = 0, grad_rms = 0;
};

Errors errors(const std::vector<VolumeSample>& got, const std::vector<VolumeSample>& ideal) {
  if (got.size() != ideal.size()) throw std::logic_error("sweep volume: resample counts differ");
  Errors e;
  double v2 = 0, g2 = 0;
  for (size_t i = 0; i < got.size(); ++i) {
    const double dv = std::abs(got[i].value - ideal[i].value);
    e.value_max = std::max(e.value_max, dv);
    v2 += dv * dv;
    for (int a = 0; a < 3; ++a) {
      const double dg = std::abs(got[i].gradient[a] - ideal[i].gradient[a]);
      e.grad_max = std::max(e.grad_max, dg);
      g2 += dg * dg;
    }
  }
  const double n = static_cast<double>(std::max<size_t>(got.size(), 1));
  e.value_rms = std::sqrt(v2 / n);
  e.grad_rms = std::sqrt(g2 / (3 * n));
  return e;
}

double ratio(uint64_t a, uint64_t b) {
  return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0;
}

// Random rays against golden before the cells count as RTL shown equal (2-3 s at rtl).
constexpr size_t kVolumeCheckItems = 2000;

std::string db(double v) { return std::isinf(v) ? "inf" : fmt::format("{:.2f}", v); }

// ---- the patent's data sets ----------------------------------------------------------------

struct DataSet {
  std::string name;
  host::VolumeScene scene;
  std::string patent;  // the patent's figure at one resample per voxel
};

// A data set on four chips as slabs along x, rays along +z one per voxel column, in the order
// of docs/volume.md's figures (i fastest) and at step 1 the same rays: from (i + 1/2, j + 1/2,
// step / 2), nz / step locations.
DataSet patent_set(bool rgba, double step) {
  DataSet d;
  host::VolumeScene& s = d.scene;
  s.format = rgba ? host::VolumeFormat::kRgba : host::VolumeFormat::kRaw;
  s.data.field = host::VolumeData::Field::kMarschnerLobb;  // the counts depend on positions only
  s.data.size =
      rgba ? std::array<uint32_t, 3>{64, 128, 128} : std::array<uint32_t, 3>{256, 128, 128};
  s.transfer = host::TransferFunction({{0, {1, 1, 1}, 0}, {255, {1, 1, 1}, 0.5}});
  s.step = step;
  s.termination.reset();  // the figures are for whole rays
  s.chips = 4;
  s.slab_axis = 0;
  s.camera.width = static_cast<int>(s.data.size[0]);
  s.camera.height = static_cast<int>(s.data.size[1]);
  d.name = rgba ? "RGBA 64x128x128" : "raw 256x128x128";
  d.patent = rgba ? "about 70 ms" : "about 0.28 s";
  return d;
}

std::vector<host::RaySetup> column_rays(const host::VolumeScene& s) {
  std::vector<host::RaySetup> rays;
  const auto count = static_cast<uint32_t>(std::lround(s.data.size[2] / s.step));
  for (uint32_t j = 0; j < s.data.size[1]; ++j) {
    for (uint32_t i = 0; i < s.data.size[0]; ++i) {
      host::RaySetup r;
      r.start = {i + 0.5, j + 0.5, s.step / 2};
      r.step = {0, 0, s.step};
      r.count = count;
      for (int a = 0; a < 3; ++a) {
        r.ray.start[static_cast<size_t>(a)] = volume::quantise(r.start[a]);
        r.ray.step[static_cast<size_t>(a)] = volume::quantise(r.step[a]);
      }
      r.ray.count = count;
      rays.push_back(r);
    }
  }
  return rays;
}

struct PatentTimes {
  VolumeFrame rgba, raw;
};

VolumeFrame run_patent_set(const DataSet& d) {
  VolumeFrame f = render::cast_volume(d.scene, host::volume_grids(d.scene), column_rays(d.scene),
                                      {Level::kGolden, d.scene.chips, nullptr});
  f.pixels.clear();
  return f;
}

}  // namespace

void sweep_volume(const VolumeSweepArgs& args) {
  const std::vector<Setting> settings = parse_volume_settings(args.settings);
  const std::string path = args.scene.empty()
                               ? std::string(TMU_SOURCE_DIR) + "/scenes/volume_marschner_lobb.json"
                               : args.scene;
  host::VolumeScene base = host::load_volume_scene(path);
  base.termination.reset();  // every location: the errors compare resample for resample
  base.chips = 1;  // one chip: golden's resamples in the ideal's order, compared one by one
  if (const std::string why =
          host::slab_problem(base.data.size, 1, base.slab_axis, host::volume_mode(base));
      !why.empty()) {
    throw InputError(path, "volume.data.size", "the sweep renders on one chip: " + why);
  }
  if (args.quick) base.camera.width = base.camera.height = 48;
  const std::vector<volume::VoxelGrid> grids = host::volume_grids(base);
  const bool raw = base.format == host::VolumeFormat::kRaw;
  if (!args.out_dir.empty()) std::filesystem::create_directories(args.out_dir);

  // The patent's data sets per step (they do not depend on W).
  std::map<double, PatentTimes, std::greater<>> patent;  // step 1, the patent's case, first
  for (const Setting& s : settings) {
    if (patent.count(s.step) || (args.quick && s.step != 1)) continue;
    patent[s.step] = {run_patent_set(patent_set(true, s.step)),
                      run_patent_set(patent_set(false, s.step))};
    fmt::print("patent data sets at step {}: {:.1f} ms, {:.3f} s\n", s.step,
               patent[s.step].rgba.unit_seconds() * 1e3, patent[s.step].raw.unit_seconds());
  }

  SweepTable table({"W,step",
                    {"value max", Mark::kModel},
                    {"value RMS", Mark::kModel},
                    {"grad max", Mark::kModel},
                    {"grad RMS", Mark::kModel},
                    {"PSNR", Mark::kModel},
                    {"acc/res", Mark::kModel},
                    {"faults/res", Mark::kModel},
                    {"frame ms", Mark::kModel},
                    {"RGBA set ms", Mark::kModel},
                    {"raw set s", Mark::kModel},
                    {"cells", Mark::kSynth},
                    {"depth", Mark::kSynth}});
  // W is a configuration port of the RTL (its datapath always blends 8 bits and masks the
  // weights), so one netlist serves every row: synthesized once, and simulated once against
  // golden on random configurations (W 1..8 among them) to earn the mark of RTL shown equal.
  const SynthFigures synth = args.synth ? synthesize("tmu_volume", {}) : SynthFigures{};
  const RtlCheck rtl = args.synth ? check_rtl("volume", {}, kVolumeCheckItems) : RtlCheck{};
  std::map<double, Render> ideals;
  for (const Setting& s : settings) {
    host::VolumeScene scene = base;
    scene.weight_bits = s.weight_bits;
    scene.step = s.step;
    if (!ideals.count(s.step)) {
      ideals[s.step] = render_at(scene, grids, Level::kIdeal);
      // The ideal against itself: what a perfect unit would score.
      const Render& id = ideals[s.step];
      const Errors none = errors(id.samples, id.samples);
      table.add({fmt::format("ideal,{}", s.step), fmt::format("{:.3f}", none.value_max),
                 fmt::format("{:.4f}", none.value_rms),
                 raw ? fmt::format("{:.3f}", none.grad_max) : "-",
                 raw ? fmt::format("{:.4f}", none.grad_rms) : "-", db(psnr(id.image, id.image)),
                 "-", "-", "-", "-", "-", "-", "-"});
      fmt::print("{}\n", table.last_row_text());
      if (!args.out_dir.empty())
        write_image(fmt::format("{}/volume_ideal_step{}.png", args.out_dir, s.step), id.image);
    }
    const Render& ideal = ideals[s.step];
    const Render golden = render_at(scene, grids, Level::kGolden);
    const Errors e = errors(golden.samples, ideal.samples);
    const render::VolumeCounters& t = golden.frame.total;
    const auto p = patent.find(s.step);
    table.add({s.name, fmt::format("{:.3f}", e.value_max), fmt::format("{:.4f}", e.value_rms),
               raw ? fmt::format("{:.3f}", e.grad_max) : "-",
               raw ? fmt::format("{:.4f}", e.grad_rms) : "-", db(psnr(golden.image, ideal.image)),
               fmt::format("{:.2f}", ratio(t.accesses, t.resamples)),
               fmt::format("{:.4f}", ratio(t.page_faults, t.resamples)),
               fmt::format("{:.2f}", golden.frame.unit_seconds() * 1e3),
               p == patent.end() ? "-" : fmt::format("{:.1f}", p->second.rgba.unit_seconds() * 1e3),
               p == patent.end() ? "-" : fmt::format("{:.3f}", p->second.raw.unit_seconds()),
               synth_cell(synth.cells, rtl.simulated()), synth_cell(synth.depth, rtl.simulated())});
    fmt::print("{}\n", table.last_row_text());
    if (!args.out_dir.empty()) {
      write_image(fmt::format("{}/volume_w{}_step{}.png", args.out_dir, s.weight_bits, s.step),
                  golden.image);
    }
  }
  table.print(args.markdown);

  // The data sets in full: per chip the slowest's counts.
  SweepTable sets({"data set, step",
                   "chips",
                   {"resamples/chip", Mark::kModel},
                   {"acc/res", Mark::kModel},
                   {"faults/res", Mark::kModel},
                   {"slow/res", Mark::kModel},
                   {"time", Mark::kModel},
                   "patent"});
  for (const auto& [step, times] : patent) {
    for (const bool rgba : {true, false}) {
      const VolumeFrame& f = rgba ? times.rgba : times.raw;
      const render::VolumeCounters& t = f.total;
      const double secs = f.unit_seconds();
      sets.add({fmt::format("{}, {}", rgba ? "RGBA 64x128x128" : "raw 256x128x128", step),
                fmt::format("{} (x slabs, ghosts {}+{})", f.chips.size(), f.plan.ghost_before,
                            f.plan.ghost_after),
                fmt::format("{}", t.resamples / f.chips.size()),
                fmt::format("{:.2f}", ratio(t.accesses, t.resamples)),
                fmt::format("{:.4f}", ratio(t.page_faults, t.resamples)),
                fmt::format("{:.4f}", ratio(t.slow_accesses, t.resamples)),
                rgba ? fmt::format("{:.1f} ms", secs * 1e3) : fmt::format("{:.3f} s", secs),
                step == 1 ? (rgba ? "about 70 ms" : "about 0.28 s") : "-"});
    }
  }
  std::string sets_md = args.markdown;
  if (const auto dot = sets_md.rfind(".md"); dot != std::string::npos)
    sets_md.insert(dot, "_patent");
  sets.print(sets_md);
}

}  // namespace tmu::texsim
