// `texsim sweep BLOCK`: what accuracy costs, side by side. trilinear: for each width setting,
// the error against the ideal model, the PSNR of a rendered test pattern, simulation speed, and
// the Yosys cell count and logic depth of the RTL at that setting. footprint: footprint assembly
// against isotropic trilinear and other anisotropic filters on a scene (sweep_footprint.hpp).
// footprint-setup: the footprint unit's setup widths (sweep_footprint_setup.hpp).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/oiio_plugin.hpp"
#include "common/test_patterns.hpp"
#include "texram/floor_view.hpp"
#include "texram/trilinear.hpp"
#include "texram/trilinear_ideal.hpp"
#include "texsim/commands.hpp"
#include "texsim/sweep_all.hpp"
#include "texsim/sweep_clipmap.hpp"
#include "texsim/sweep_deflection.hpp"
#include "texsim/sweep_footprint.hpp"
#include "texsim/sweep_footprint_setup.hpp"
#include "texsim/sweep_mipgen.hpp"
#include "texsim/sweep_nurbs.hpp"
#include "texsim/sweep_perlin.hpp"
#include "texsim/sweep_support.hpp"
#include "texsim/sweep_volume.hpp"

namespace tmu::texsim {
namespace {

using texram::SamplerConfig;
using texram::TexramTexture;
using texram::Widths;

// The rendered test pattern: the floor view of a texture, golden against ideal.
struct ViewResult {
  double psnr = 0;
  ImageRgb8 golden, ideal;
  ImageRgb8 error;  // |golden - ideal|, largest channel, times 16: where the widths cost
  double golden_seconds = 0;
  size_t samples = 0;
};

ViewResult render_view(const TexramTexture& tex, const SamplerConfig& config, int w, int h) {
  const auto view =
      texram::floor_view(w, h, tex.geometry.texel_width(0), tex.geometry.texel_height(0));
  const texram::IdealTexture ideal_tex = texram::ideal_texture(tex.source);
  ViewResult r;
  r.golden = ImageRgb8(w, h);
  r.ideal = ImageRgb8(w, h);
  r.error = ImageRgb8(w, h);
  std::vector<texram::Request> requests;
  for (const auto& v : view) {
    requests.push_back({static_cast<int32_t>(formats::TexCoord::from_double(v.u).raw()),
                        static_cast<int32_t>(formats::TexCoord::from_double(v.v).raw()),
                        static_cast<int32_t>(formats::Lod::from_double(v.lambda).raw()), 0});
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<uint32_t> out(requests.size());
  for (size_t i = 0; i < requests.size(); ++i) out[i] = texram::sample(tex, config, requests[i]);
  r.golden_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.samples = requests.size();
  double se = 0;
  for (size_t i = 0; i < view.size(); ++i) {
    const auto ideal =
        texram::ideal_sample(ideal_tex, config, view[i].u, view[i].v, view[i].lambda);
    Rgb8& g = r.golden.at(view[i].x, view[i].y);
    Rgb8& d = r.ideal.at(view[i].x, view[i].y);
    g = {static_cast<uint8_t>(out[i] >> 24), static_cast<uint8_t>(out[i] >> 16),
         static_cast<uint8_t>(out[i] >> 8)};
    d = {static_cast<uint8_t>(std::lround(ideal[0])), static_cast<uint8_t>(std::lround(ideal[1])),
         static_cast<uint8_t>(std::lround(ideal[2]))};
    double worst = 0;
    for (int c = 0; c < 3; ++c) {
      const double e = texram::channel(out[i], c) - ideal[static_cast<size_t>(c)];
      se += e * e;
      worst = std::max(worst, std::abs(e));
    }
    const auto shown = static_cast<uint8_t>(std::min(255.0, 16.0 * worst));
    r.error.at(view[i].x, view[i].y) = {shown, shown, shown};
  }
  const double mse = se / (3.0 * static_cast<double>(view.size()));
  r.psnr = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : INFINITY;
  return r;
}

// Random requests on the port grid over every level: max and mean absolute error.
std::pair<double, double> random_error(const TexramTexture& tex, const SamplerConfig& config,
                                       int count) {
  std::mt19937 rng(7);
  const int w = static_cast<int>(tex.geometry.texel_width(0)),
            h = static_cast<int>(tex.geometry.texel_height(0));
  const texram::IdealTexture ideal_tex = texram::ideal_texture(tex.source);
  double max_err = 0, sum = 0;
  for (int i = 0; i < count; ++i) {
    const texram::Request r{static_cast<int32_t>(rng() % (w * 256)),
                            static_cast<int32_t>(rng() % (h * 256)),
                            static_cast<int32_t>(rng() % (tex.geometry.levels() * 256)), 0};
    const uint32_t g = texram::sample(tex, config, r);
    const auto ideal =
        texram::ideal_sample(ideal_tex, config, r.u / 256.0, r.v / 256.0, r.lambda / 256.0);
    for (int c = 0; c < 4; ++c) {
      const double e = std::abs(texram::channel(g, c) - ideal[static_cast<size_t>(c)]);
      max_err = std::max(max_err, e);
      sum += e;
    }
  }
  return {max_err, sum / (4.0 * count)};
}

std::vector<Widths> parse_widths(const std::string& text) {
  std::vector<Widths> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ';');) {
    Widths w;
    if (std::sscanf(item.c_str(), "%d,%d,%d", &w.sub_texel, &w.weight, &w.lod_frac) != 3 ||
        w.sub_texel < 1 || w.sub_texel > 8 || w.weight < 1 || w.weight > 8 || w.lod_frac < 1 ||
        w.lod_frac > 8) {
      throw InputError("--settings", "", "'" + item + "' is not S,W,L with each 1..8");
    }
    out.push_back(w);
  }
  if (out.empty()) throw InputError("--settings", "", "no settings");
  return out;
}

}  // namespace

void sweep_trilinear(const SweepArgs& args) {
  const std::vector<Widths> settings = parse_widths(args.settings);
  const TexramTexture photo =
      texram::import_image(patterns::default_image(256, 256), texram::TexelKind::kTrueColour);
  const TexramTexture checker =
      texram::import_image(patterns::checker(256, 256, 16, {30, 30, 30}, {230, 230, 230}),
                           texram::TexelKind::kTrueColour);
  SamplerConfig base;
  base.kind = texram::TexelKind::kTrueColour;
  base.filter = texram::Filter::kTrilinear;

  // Errors and golden's speed are the golden model's; rtl where a model of the setting was
  // verilated, run on the checker's floor view against golden; Yosys at every setting.
  SweepTable table({"S,W,L",
                    {"max err", Mark::kModel},
                    {"mean err", Mark::kModel},
                    {"PSNR checker", Mark::kModel},
                    {"PSNR photo", Mark::kModel},
                    {"golden Ms/s", Mark::kModel},
                    {"rtl Ms/s", Mark::kSim},
                    {"rtl = golden", Mark::kSim},
                    {"cells", Mark::kSynth},
                    {"logic", Mark::kSynth},
                    {"depth", Mark::kSynth}});
  for (const Widths& w : settings) {
    SamplerConfig c = base;
    c.widths = w;
    const auto [max_err, mean_err] = random_error(photo, c, args.requests);
    const ViewResult vc = render_view(checker, c, 256, 192);
    const ViewResult vp = render_view(photo, c, 256, 192);
    const std::string name = fmt::format("{},{},{}", w.sub_texel, w.weight, w.lod_frac);
    if (!args.out_dir.empty()) {
      std::filesystem::create_directories(args.out_dir);
      const std::string stem = args.out_dir + "/trilinear_" +
                               fmt::format("s{}w{}l{}", w.sub_texel, w.weight, w.lod_frac);
      write_image(stem + ".png", vc.golden);
      write_image(stem + "_error.png", vc.error);
      if (&w == &settings.front()) write_image(args.out_dir + "/trilinear_ideal.png", vc.ideal);
    }
    const RtlSpeed rtl = measure_trilinear_rtl(w, checker, c, args);
    const SynthFigures synth = args.synth
                                   ? synthesize("tmu_trilinear", {{"SubTexelBits", w.sub_texel},
                                                                  {"WeightBits", w.weight},
                                                                  {"LodFracBits", w.lod_frac}})
                                   : SynthFigures{};
    table.add({name, fmt::format("{:.3f}", max_err), fmt::format("{:.4f}", mean_err),
               fmt::format("{:.2f}", vc.psnr), fmt::format("{:.2f}", vp.psnr),
               fmt::format("{:.2f}", static_cast<double>(vc.samples + vp.samples) /
                                         (vc.golden_seconds + vp.golden_seconds) / 1e6),
               rtl.text(), rtl.verdict, synth_cell(synth.cells, rtl.simulated()),
               synth_cell(synth.logic, rtl.simulated()), synth_cell(synth.depth, rtl.simulated())});
    fmt::print("{}\n", table.last_row_text());
  }
  table.print(args.markdown);
}

void add_sweep_command(CLI::App& app, ExitCode&) {
  auto* cmd = app.add_subcommand(
      "sweep",
      "Accuracy against cost. trilinear: error, PSNR, simulation speed and cells per width "
      "setting.\n"
      "footprint: footprint assembly (N max 2..16) against isotropic trilinear, the ideal "
      "footprint unit and\n"
      "OpenImageIO's anisotropic filter on a scene at grazing angles: PSNR against a supersampled "
      "reference,\n"
      "probes and predicted cycles per pixel, wall time (docs/sweeps/footprint.md).\n"
      "footprint-setup: the footprint setup's widths D,T,F: lambda error and N against the ideal "
      "setup,\n"
      "speed, cells (docs/footprint.md).\n"
      "deflection: bump and reflection mapping (001 §4-5) per sphere grid and table widths "
      "A,E,M,W: angle\n"
      "errors of the deflected normal and the reflection vector, PSNR, table bits, hit rate, "
      "cells (docs/deflection.md).\n"
      "perlin: the noise unit's widths F,S,B,X: noise and fractal-sum error against the ideal, "
      "PSNR of each\n"
      "procedural material of a scene, fade-table bits, speed, cells; both fractal "
      "configurations (docs/perlin.md).\n"
      "mipgen: the mipmap generator's rounding (000 §12) per carry: each level's error against "
      "the exact box\n"
      "means of level 0, the carried bits in the line FIFOs, cells (docs/texram.md).\n"
      "clipmap: the clip-map (003) per tile size and substitution rule on the fly-over: texels "
      "resident, loaded\n"
      "per frame, wayward samples, the frames' error against the whole pyramid's; loads against "
      "speed; rtl = golden,\n"
      "cycles and cells at the default tile (docs/clipmap.md).\n"
      "nurbs: NURBS texturing (004) per tessellation threshold (MC, DC, TC, combined; order tc): "
      "triangles,\n"
      "front-end time, cycles, PSNR against an ideal order-pc reference on the surface; the tau "
      "unit per grid\n"
      "size and interpolation against the functional map, rtl = golden; the orders pc, tc, "
      "texture, composed\n"
      "on a sphere (docs/nurbs.md).\n"
      "volume: the volume unit (000 §13) per weight bits and step W,step on a volume scene: the "
      "resamples' value and\n"
      "gradient error against the ideal, the frame's PSNR, accesses and page faults per "
      "resample; the patent's\n"
      "two data sets on four chips at 30 ns an access beside its 70 ms and 0.28 s "
      "(docs/volume.md).\n"
      "all: every sweep above, the model-level table (texsim levels) and the default scene at "
      "every engine, with\n"
      "a plot per block (scripts/plot_accuracy.py): writes DIR/accuracy.md and DIR/accuracy/ "
      "(--out DIR, default docs).\n"
      "Every column names how its figures were obtained, a cell obtained otherwise its own: "
      "[sim] [synth] [synth only]\n"
      "[formula] [model] (docs/conventions.md, \"Figures in documents\"); the hardware runs "
      "against golden wherever\n"
      "the build has a model of the setting (rtl = golden).");
  auto args = std::make_shared<SweepArgs>();
  auto fp = std::make_shared<FootprintSweepArgs>();
  cmd->add_option("block", args->block,
                  "trilinear | footprint | footprint-setup | deflection | perlin | mipgen | "
                  "clipmap | nurbs | volume | all")
      ->required()
      ->check(CLI::IsMember({"trilinear", "footprint", "footprint-setup", "deflection", "perlin",
                             "mipgen", "clipmap", "nurbs", "volume", "all"}));
  cmd->add_option("--settings", args->settings,
                  "trilinear: width settings S,W,L separated by ';' (footprint-setup: D,T,F; "
                  "default " +
                      FootprintSetupSweepArgs{}.settings + "; deflection: A,E,M,W, default " +
                      DeflectionSweepArgs{}.settings + "; perlin: F,S,B,X, default " +
                      PerlinSweepArgs{}.settings + "; mipgen: carries 0..20, default " +
                      MipgenSweepArgs{}.settings + "; clipmap: log2 tile sides, default " +
                      ClipmapSweepArgs{}.settings +
                      "; nurbs: tessellation rows of mc=, dc=, tc=, g=, max= terms joined by '+', "
                      "default " +
                      NurbsSweepArgs{}.settings + "; volume: W,step, default " +
                      VolumeSweepArgs{}.settings + ")")
      ->capture_default_str();
  cmd->add_option("--requests", args->requests,
                  "trilinear, footprint-setup, nurbs: random requests for the error statistics "
                  "(footprint-setup default 200000; nurbs: (s, t) per tau row, default 200000)")
      ->capture_default_str();
  cmd->add_option("--out", args->out_dir,
                  "Write the rendered pictures (and footprint: error maps, side by side) here");
  cmd->add_option("--markdown", args->markdown, "Also write the table as Markdown to this file");
  cmd->add_flag(
      "--no-synth", [args](int64_t) { args->synth = false; },
      "trilinear, footprint-setup, deflection: skip the Yosys runs (they take minutes)");
  cmd->add_option(
         "--scene", fp->scene,
         "footprint: the scene (default scenes/grazing.json); deflection: the fragments of its "
         "materials with a deflection chain (default a synthetic bump-mapped sphere); perlin: "
         "its procedural materials (default scenes/procedural.json); nurbs: the scene of the "
         "threshold table (default scenes/nurbs_freeform.json); volume: a volume scene (default "
         "scenes/volume_marschner_lobb.json); all: the scene rendered at "
         "every "
         "engine (default scenes/default.json)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--k", fp->k,
                  "footprint: the reference's sub-pixels per side (default 8, 4 with --quick; 1: "
                  "per-pixel supersampled footprint)")
      ->check(CLI::Range(1, 16));
  cmd->add_flag("--quick", fp->quick,
                "footprint: half the frame and k = 4; nurbs: half the frames' resolution, 20000 "
                "tau samples, 1000 at rtl; volume: a 48 x 48 frame, the data sets at step 1 only "
                "(for tests)");
  auto log2_virtual = std::make_shared<int>(ClipmapSweepArgs{}.log2_virtual);
  cmd->add_option("--log2-virtual", *log2_virtual,
                  "clipmap: log2 of the terrain's side (up to 10 the frames are also rendered from "
                  "the whole pyramid for their error; 15 is 003's 32k, a long run)")
      ->check(CLI::Range(3, 15))
      ->capture_default_str();
  auto image = std::make_shared<std::string>();
  cmd->add_option("--image", *image,
                  "mipgen: the image whose planes are filtered (sides powers of two up to 1024; "
                  "default the photo-like field, 512 x 512)")
      ->check(CLI::ExistingFile);
  cmd->callback([args, fp, image, log2_virtual, cmd] {
    if (args->block != "mipgen" && !image->empty()) {
      throw CLI::ValidationError("--image", "only for `sweep mipgen`");
    }
    load_oiio_plugin();  // before any sweep's clock starts
    if (args->block == "all") {
      for (const char* o : {"--settings", "--requests", "--k", "--quick", "--markdown"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep all`");
      }
      SweepAllArgs a;
      if (!args->out_dir.empty()) a.out_dir = args->out_dir;
      a.synth = args->synth;
      a.scene = fp->scene;
      sweep_all(a);
    } else if (args->block == "trilinear") {
      for (const char* o : {"--scene", "--k", "--quick"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "only for `sweep footprint`");
      }
      sweep_trilinear(*args);
    } else if (args->block == "footprint-setup") {
      for (const char* o : {"--scene", "--k", "--quick", "--out"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep footprint-setup`");
      }
      FootprintSetupSweepArgs a;
      if (cmd->count("--settings") > 0) a.settings = args->settings;
      if (cmd->count("--requests") > 0) a.count = args->requests;
      a.synth = args->synth;
      a.markdown = args->markdown;
      sweep_footprint_setup(a);
    } else if (args->block == "perlin") {
      for (const char* o : {"--k", "--quick"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep perlin`");
      }
      PerlinSweepArgs a;
      if (cmd->count("--settings") > 0) a.settings = args->settings;
      if (cmd->count("--requests") > 0) a.points = args->requests;
      a.scene = fp->scene;
      a.synth = args->synth;
      a.out_dir = args->out_dir;
      a.markdown = args->markdown;
      sweep_perlin(a);
    } else if (args->block == "deflection") {
      for (const char* o : {"--k", "--quick", "--requests"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep deflection`");
      }
      DeflectionSweepArgs a;
      a.scene = fp->scene;
      if (cmd->count("--settings") > 0) a.settings = args->settings;
      a.synth = args->synth;
      a.out_dir = args->out_dir;
      a.markdown = args->markdown;
      sweep_deflection(a);
    } else if (args->block == "mipgen") {
      for (const char* o : {"--scene", "--k", "--quick", "--requests", "--out"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep mipgen`");
      }
      MipgenSweepArgs a;
      if (cmd->count("--settings") > 0) a.settings = args->settings;
      a.image = *image;
      a.synth = args->synth;
      a.markdown = args->markdown;
      sweep_mipgen(a);
    } else if (args->block == "clipmap") {
      for (const char* o : {"--k", "--quick", "--requests"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep clipmap`");
      }
      ClipmapSweepArgs a;
      if (cmd->count("--settings") > 0) a.settings = args->settings;
      a.log2_virtual = *log2_virtual;
      a.scene = fp->scene;
      a.work_dir = args->out_dir;
      a.synth = args->synth;
      a.markdown = args->markdown;
      sweep_clipmap(a);
    } else if (args->block == "nurbs") {
      for (const char* o : {"--k", "--out"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep nurbs`");
      }
      if (args->requests < 1) throw CLI::ValidationError("--requests", "at least 1");
      NurbsSweepArgs a;
      if (cmd->count("--settings") > 0) a.settings = args->settings;
      if (cmd->count("--requests") > 0) a.tau_samples = static_cast<size_t>(args->requests);
      a.scene = fp->scene;
      a.quick = fp->quick;
      a.markdown = args->markdown;
      sweep_nurbs(a);
    } else if (args->block == "volume") {
      for (const char* o : {"--k", "--requests"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "not for `sweep volume`");
      }
      VolumeSweepArgs a;
      a.synth = args->synth;
      if (cmd->count("--settings") > 0) a.settings = args->settings;
      a.scene = fp->scene;
      a.quick = fp->quick;
      a.out_dir = args->out_dir;
      a.markdown = args->markdown;
      sweep_volume(a);
    } else if (args->block == "footprint") {
      for (const char* o : {"--settings", "--requests", "--no-synth"}) {
        if (cmd->count(o) > 0) throw CLI::ValidationError(o, "only for `sweep trilinear`");
      }
      FootprintSweepArgs a = *fp;
      a.out_dir = args->out_dir;
      a.markdown = args->markdown;
      sweep_footprint(a);
    }
  });
}

}  // namespace tmu::texsim
