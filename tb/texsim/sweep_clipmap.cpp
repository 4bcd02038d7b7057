#include "texsim/sweep_clipmap.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "common/error.hpp"
#include "render/flyover.hpp"
#include "render/unit_check.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

namespace fs = std::filesystem;
using clipmap::Substitution;

std::vector<int> parse_tiles(const std::string& text, int log2_virtual) {
  std::vector<int> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ';');) {
    size_t end = 0;
    int t = -1;
    try {
      t = std::stoi(item, &end);
    } catch (const std::exception&) {
    }
    if (end != item.size() || t < clipmap::kMinLog2Tile || t >= log2_virtual) {
      throw InputError("--settings", "",
                       fmt::format("'{}' is not a log2 tile side {}..{}", item,
                                   clipmap::kMinLog2Tile, log2_virtual - 1));
    }
    out.push_back(t);
  }
  if (out.empty()) throw InputError("--settings", "", "no settings");
  return out;
}

// Texels of the clip-map and of the whole mipmap of a 2^v texture with 2^t tiles.
struct Residency {
  double resident = 0, full = 0;
};
Residency residency(int v, int t) {
  Residency r;
  for (int l = 0; l <= v; ++l) {
    const double side = std::ldexp(1.0, std::min(v - l, t));
    r.resident += side * side;
    r.full += std::ldexp(1.0, 2 * (v - l));
  }
  return r;
}

// Error of the frames against the reference's, over RGB: PSNR and mean absolute error.
struct FrameError {
  double psnr = INFINITY, mean = 0;
};
FrameError frame_error(const std::vector<ImageRgb8>& got, const std::vector<ImageRgb8>& ref) {
  double se = 0, sum = 0, n = 0;
  for (size_t f = 0; f < got.size(); ++f) {
    for (size_t i = 0; i < got[f].pixels.size(); ++i) {
      const Rgb8 a = got[f].pixels[i], b = ref[f].pixels[i];
      for (const double e : {double(a.r) - b.r, double(a.g) - b.g, double(a.b) - b.b}) {
        se += e * e;
        sum += std::abs(e);
        n += 1;
      }
    }
  }
  FrameError e;
  e.mean = sum / n;
  if (se > 0) e.psnr = 10 * std::log10(255.0 * 255.0 * n / se);
  return e;
}

double mean_loads(const render::FlyoverRun& run) {  // frames after the first
  double loads = 0;
  for (size_t f = 1; f < run.frames.size(); ++f) loads += double(run.frames[f].loads);
  return run.frames.size() > 1 ? loads / double(run.frames.size() - 1) : 0;
}

double wayward_share(const render::FlyoverRun& run) {
  double w = 0, n = 0;
  for (const render::FrameReport& r : run.frames) {
    w += double(r.wayward);
    n += double(r.samples);
  }
  return n > 0 ? w / n : 0;
}

std::string side_name(int t) { return fmt::format("{}", 1 << t); }

}  // namespace

void sweep_clipmap(const ClipmapSweepArgs& args) {
  const std::string scene =
      args.scene.empty() ? std::string(TMU_SOURCE_DIR) + "/scenes/flyover.json" : args.scene;
  const fs::path work = args.work_dir.empty() ? fs::temp_directory_path() / "tmu_sweep_clipmap"
                                              : fs::path(args.work_dir);
  fs::create_directories(work);
  render::Flyover fo = render::load_flyover(scene, work.string());
  if (fo.terrain_log2 == 0) throw InputError(scene, "flyover", "the sweep generates its terrain");
  fo.terrain_log2 = fo.config.log2_virtual = args.log2_virtual;
  fo.texture = (work / fmt::format("terrain-{}-{}.tx", fo.terrain_log2, fo.terrain_seed)).string();
  render::make_virtual_texture(fo, std::cout);
  const std::vector<int> tiles = parse_tiles(args.settings, fo.config.log2_virtual);
  const int last = fo.frames() - 1;
  const int v = fo.config.log2_virtual;
  fmt::print("clip-map sweep: {} frames of {}, virtual {} x {}, tiles {}\n", fo.frames(), scene,
             1 << v, 1 << v, args.settings);

  // The reference: every level resident (one tile as large as the texture, nothing clipped).
  std::vector<ImageRgb8> reference;
  const bool referenced = v <= clipmap::kMaxLog2Tile;
  if (referenced) {
    render::Flyover whole = fo;
    whole.config.log2_tile = v;
    reference = render::run_flyover(whole, render::Level::kGolden, 0, last).images;
  }

  SweepTable table({"tile,rule", Column("resident texels", Mark::kFormula),
                    Column("of full %", Mark::kFormula), Column("wayward %", Mark::kModel),
                    Column("loads/frame", Mark::kModel), Column("PSNR dB", Mark::kModel),
                    Column("mean err", Mark::kModel)});
  for (const int t : tiles) {
    for (const Substitution rule : {Substitution::kPerSample, Substitution::kPerTap}) {
      render::Flyover s = fo;
      s.config.log2_tile = t;
      s.config.substitution = rule;
      const render::FlyoverRun run = render::run_flyover(s, render::Level::kGolden, 0, last);
      const Residency r = residency(v, t);
      const FrameError e = referenced ? frame_error(run.images, reference) : FrameError{NAN, NAN};
      table.add(
          {fmt::format("{} {}", side_name(t),
                       rule == Substitution::kPerTap ? "per-tap" : "per-sample"),
           fmt::format("{:.0f}", r.resident), fmt::format("{:.2f}", 100 * r.resident / r.full),
           fmt::format("{:.1f}", 100 * wayward_share(run)), fmt::format("{:.0f}", mean_loads(run)),
           std::isinf(e.psnr) ? "inf" : fmt::format("{:.2f}", e.psnr),
           fmt::format("{:.3f}", e.mean)});
      fmt::print("  {}\n", table.last_row_text());
    }
  }
  const auto beside = [&](const char* suffix) {
    if (args.markdown.empty()) return std::string();
    const fs::path p(args.markdown);
    return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
  };
  table.print(args.markdown);

  // Texels loaded per frame against the camera's speed: every k-th frame of the path (the
  // camera k times as fast), at the default tile.
  const int default_tile = fo.config.log2_tile <= v - 1 ? fo.config.log2_tile : tiles.front();
  SweepTable speed({"speed", Column("loads/frame", Mark::kModel),
                    Column("level-0 rows/frame", Mark::kModel), Column("wayward %", Mark::kModel)});
  for (const int step : {1, 2, 4}) {
    render::Flyover s = fo;
    s.config.log2_tile = default_tile;
    const render::FlyoverRun run = render::run_flyover(s, render::Level::kGolden, 0, last, step);
    double rows = 0;
    for (size_t f = 1; f < run.frames.size(); ++f) rows += run.frames[f].rows[0];
    speed.add(
        {fmt::format("{}x", step), fmt::format("{:.0f}", mean_loads(run)),
         fmt::format("{:.1f}", run.frames.size() > 1 ? rows / double(run.frames.size() - 1) : 0),
         fmt::format("{:.1f}", 100 * wayward_share(run))});
  }
  speed.print(beside("_speed"));

  // The hardware at the default: rtl against golden, cycles, cells (the unit is the same for
  // every tile size: its registers take the sizes).
  SweepTable hw({"configuration", "rtl = golden", Column("cycles/frame", Mark::kSim),
                 Column("cycles/sample", Mark::kSim), Column("cells", Mark::kSynth),
                 Column("logic", Mark::kSynth), Column("depth", Mark::kSynth)});
  {
    render::Flyover s = fo;
    s.config.log2_tile = default_tile;
    render::FlyoverRun rtl = render::run_flyover(s, render::Level::kRtl, 0, last);
    render::UnitRun golden = rtl.unit;
    golden.result = {};
    render::run_unit(golden, render::Level::kGolden, {});
    const bool match = render::check_units({rtl.unit}, {golden}).match();
    double cycles = 0, samples = 0;
    for (size_t f = 1; f < rtl.frames.size(); ++f) {
      cycles += double(rtl.frames[f].cycles);
      samples += double(rtl.frames[f].samples);
    }
    const SynthFigures fig = args.synth ? synthesize("tmu_clipmap", {}) : SynthFigures{};
    hw.add({fmt::format("tile {}, per-sample, frames 1..{}", side_name(default_tile), last),
            match ? "yes" : "NO", fmt::format("{:.0f}", cycles / double(rtl.frames.size() - 1)),
            fmt::format("{:.2f}", cycles / samples), synth_cell(fig.cells, match),
            synth_cell(fig.logic, match), synth_cell(fig.depth, match)});
  }
  hw.print(beside("_hardware"));

  // 003's configuration by formula: 32k x 32k with 1k tiles.
  const Residency patent = residency(15, 10);
  fmt::print(
      "003's configuration (formula): 32768 x 32768 with 1024 x 1024 tiles keeps {:.2f} M of "
      "{:.3f} G texels ({:.2f} %, {:.1f} % saved); the patent writes about 6 M of 1.365 G, 99.6 % "
      "saved (its G is 2^30).\n",
      patent.resident / 1e6, patent.full / 1e9, 100 * patent.resident / patent.full,
      100 - 100 * patent.resident / patent.full);
}

}  // namespace tmu::texsim
