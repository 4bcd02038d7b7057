#include "texsim/sweep_all.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "common/atomic_file.hpp"
#include "common/read_file.hpp"
#include "texsim/model_levels.hpp"
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

namespace fs = std::filesystem;

// One block's part of the document: what its settings are, how to read its columns, its
// table (the Markdown its sweep wrote) and its plot (scripts/plot_accuracy.py).
struct Section {
  std::string title, stem, about, doc;
};

const Section kSections[] = {
    {"Trilinear unit (000 §2, §5, §6)", "trilinear",
     "Settings S,W,L: sub-texel, weight and lambda-fraction bits; 8,8,8 is the default. Error: "
     "golden against the ideal (double) sampler over 20 000 random requests (8-bit levels) and "
     "the PSNR of a rendered floor. Cost: cells (memories as flops) and logic (memories as RAM "
     "macros), depth; simulation speed in million samples per second, rtl where the build "
     "verilated the setting. Cycles per pixel, not in the table, do not depend on the widths: "
     "one access per byte plane (1 for one-plane textures, 4 for RGBA8888), a formula.",
     "texram.md"},
    {"Footprint setup (000 §10, eq. 19-20)", "footprint_setup",
     "Settings D,T,F: derivative bits, log2-table bits, log-fraction bits; 12,7,8 is the "
     "default. Error: lambda against the ideal setup (levels) and how often the probe count N "
     "differs. Cost: cells, depth, and golden setups per second; rtl = golden where the build "
     "verilated the setup at that setting.",
     "footprint.md"},
    {"Footprint assembly (000 §10)", "footprint",
     "Variants: isotropic trilinear, footprint assembly with at most N probes (N max 16 is the "
     "default), the ideal footprint unit, OpenImageIO's anisotropic filter, on a scene at "
     "grazing angles against a supersampled reference. Error: PSNR and max / mean error. Cost: "
     "probes and cycles per pixel (the page model's prediction for golden's memory accesses, no "
     "RTL run), wall time. Every figure is the row's model's.",
     "footprint.md"},
    {"Bump and reflection mapping (001 §4-5)", "deflection",
     "Settings A,E,M,W per sphere grid: grid bits, angle-table exponent and mantissa bits, "
     "deflection word; 9,4,5,10 (512x256) is the default. Error: angle of the deflected normal "
     "(N) and of the reflection vector (R) against the ideal, PSNR of the shaded views. Cost: "
     "table bits, the golden deflection cache's hit rate and cycles per bumped pixel (one plus "
     "the map memory's latency per miss), golden time per pixel, whether each unit's RTL at the "
     "setting equals golden on its block's stimulus, and the cells of the encoder, the "
     "deflection unit and the coordinate generator (n/a: a setting beyond the RTL's port "
     "formats, a grid above 512x256 or W above 10, is golden only).",
     "deflection.md"},
    {"Procedural noise (002 §4.1)", "perlin",
     "Settings F,S,B,X: fade-table index bits, fade-value bits, lerp weight bits, extra lerp "
     "bits; 8,8,8,4 is the default. Error: the noise P and the fractal sums against the ideal "
     "(double) noise, PSNR of each material of the procedural scene. Cost: fade-table bits, "
     "golden time per sample, the noise unit's cells and depth (its RTL verilated at 8,8,8,4 "
     "only). Cycles per sample: below, measured on the RTL.",
     "perlin.md"},
    {"Mipmap generator (000 §12)", "mipgen",
     "Settings: the carry, how many fraction bits of each level's unrounded 2x2 sums the line "
     "FIFOs keep for the next level (0: every level rounded from the rounded one below, the old "
     "rule; 20: every sum exact, the default). Error: each level of golden's pyramid against the "
     "exact box mean of level 0 (the independent ideal pyramid), R, G and B of the photo-like "
     "field at 512 x 512, mean (signed) / max abs in 8-bit levels. Cost: FIFO and hold bits at "
     "1024 x 1024 (a formula), cells, logic (FIFOs as RAM macros) and depth of tmu_mipgen.",
     "texram.md"},
    {"Clip-map (003)", "clipmap",
     "Settings: the tile side and the substitution rule, on the fly-over (scenes/flyover.json) "
     "over its terrain at 1024 x 1024, so that the same frames can be rendered with every level "
     "resident. Cost: texels resident against the whole mipmap (a formula) and texels loaded per "
     "frame after the first (the tile manager's). Error: the share of wayward samples (a "
     "substitution served them), the frames' PSNR and mean error against the whole pyramid's "
     "(golden both: what clipping costs, not what fixed point costs). Below: loads against the "
     "camera's speed, and the unit's hardware at the default tile.",
     "clipmap.md"},
    {"NURBS texturing (004)", "nurbs",
     "Settings: the tessellation thresholds of claims 8-11 (MC in modelling units, DC in pixels, "
     "TC in texels of level 0, and DC with TC averaged by g = mean), up to 1024 steps a patch and "
     "direction so that the thresholds decide, on scenes/nurbs_freeform.json with every material "
     "in order tc (claim 16: tau at the vertices, (u, v) interpolated, so a threshold moves both "
     "the geometry and the texture) and sampled by the trilinear unit at the pixel's lambda (no "
     "footprint marcher, whose power-of-two probe count jumps with small changes of r1 and r2, "
     "and not claim 12's level, which follows the steps: both would hide the tessellation's "
     "error; claim 12's level is in the orders table). Error: the golden frame against the "
     "reference, the same "
     "scene at the ideal engine in order pc, tessellated through quarter-pixel steps (DC 0.25) "
     "and then every fragment moved onto the true surface along its pixel's ray (Newton on the "
     "patch: exact (s, t), screen derivatives and normal), tau applied per pixel in double "
     "precision; PSNR and max / mean error (RGB, "
     "8-bit levels) over the pixels both frames cover, the pixels only one covers counted (the "
     "max error is a few isolated pixels near edges until the steps are about a pixel). Cost: "
     "triangles, the front end's time (tessellation and rasterization) and the units' cycles "
     "(golden's, the page model's prediction: the texture's accesses, nearly the same for every "
     "row). "
     "Below: the tau unit's grid against the functional map, and the four composition orders.",
     "nurbs.md"},
    {"Volume rendering (000 §13)", "volume",
     "Settings W,step: the volume unit's weight bits and the ray's step in voxels; 8,1 is the "
     "default. The Marschner-Lobb scene (scenes/volume_marschner_lobb.json, raw, shaded) "
     "rendered without early termination at golden and at ideal. Error: every resample's value "
     "and gradient component (voxel values, and per voxel) against the ideal's at the real "
     "ray's location (the host's quantisation of start and step, the truncated weights, the "
     "roundings), max and RMS; the frame's PSNR against the ideal frame (both 8-bit; the rows "
     "ideal are the ideal against itself). Cost: accesses and page faults per resample and the "
     "frame's unit time at 30 ns an access (the page model's counts), and the patent's two "
     "data sets on four chips at that step (below in full). Cells and depth: tmu_volume, one "
     "netlist for every W (W is a configuration port; its 8-bit blend masks the weights).",
     "volume.md"},
};

void run_block_sweeps(const SweepAllArgs& args, const fs::path& data) {
  auto md = [&](const char* stem) { return (data / (std::string(stem) + ".md")).string(); };
  SweepArgs tri;
  tri.block = "trilinear";
  tri.synth = args.synth;
  tri.markdown = md("trilinear");
  sweep_trilinear(tri);

  FootprintSetupSweepArgs setup;
  setup.synth = args.synth;
  setup.markdown = md("footprint_setup");
  sweep_footprint_setup(setup);

  FootprintSweepArgs fp;
  fp.markdown = md("footprint");
  sweep_footprint(fp);

  DeflectionSweepArgs deflection;
  deflection.synth = args.synth;
  deflection.markdown = md("deflection");
  sweep_deflection(deflection);

  PerlinSweepArgs perlin;
  perlin.synth = args.synth;
  perlin.markdown = md("perlin");
  sweep_perlin(perlin);

  MipgenSweepArgs mipgen;
  mipgen.synth = args.synth;
  mipgen.markdown = md("mipgen");
  sweep_mipgen(mipgen);

  ClipmapSweepArgs clip;
  clip.synth = args.synth;
  clip.markdown = md("clipmap");
  sweep_clipmap(clip);

  NurbsSweepArgs nurbs;
  nurbs.markdown = md("nurbs");
  sweep_nurbs(nurbs);

  VolumeSweepArgs volume;
  volume.synth = args.synth;
  volume.markdown = md("volume");
  sweep_volume(volume);
}

// The first line of `path` holding `key` (e.g. "model name" in /proc/cpuinfo), after its ':'.
std::string proc_field(const char* path, const std::string& key) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with(key) && line.find(':') != std::string::npos) {
      return line.substr(line.find_first_not_of(" \t", line.find(':') + 1));
    }
  }
  return "unknown";
}

// The 1-minute load average: speed figures are only comparable at similar loads.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  return in >> one ? one : "unknown";
}

// Where and under what load the figures were taken, and how many of the Yosys figures were
// computed in this run rather than read from the cache (sweep_support.hpp).
struct RunContext {
  double minutes = 0;
  std::string load_start, load_end;
};

std::string provenance(const SweepAllArgs& args, const RunContext& run) {
  const SynthCounts synth = synth_counts();
  return fmt::format(
      "GENERATED by `texsim sweep all{}`; do not edit: run it again. This run: {:.0f} minutes on "
      "{} ({} hardware threads), load average {} at the start and {} at the end; Yosys ran {} "
      "times and {} figures came from its cache (build/synth_cache/).",
      args.synth ? "" : " --no-synth", run.minutes, proc_field("/proc/cpuinfo", "model name"),
      std::thread::hardware_concurrency(), run.load_start, run.load_end, synth.run, synth.cached);
}

// `path` relative to the source tree when it is inside it: the document is checked in.
std::string display_path(const std::string& path) {
  const fs::path rel = fs::path(path).lexically_relative(TMU_SOURCE_DIR);
  return rel.empty() || *rel.begin() == ".." ? path : rel.string();
}

// What follows a section's table and plot: its further tables.
std::string section_tail(const std::string& stem, const fs::path& data) {
  if (stem == "perlin") {
    return "### Procedural noise: the fractal unit's configurations\n\n" +
           read_file(data / "perlin_configs.md") + "\n";
  }
  if (stem == "clipmap") {
    return "### Clip-map: texels loaded against the camera's speed (every k-th frame), and the "
           "hardware\n\n" +
           read_file(data / "clipmap_speed.md") + "\n" + read_file(data / "clipmap_hardware.md") +
           "\n003's configuration, 32k x 32k with 1k tiles, by formula: 6.64 M of 1.432 G texels "
           "resident (0.46 %, 99.5 % saved; the patent writes about 6 M of 1.365 G, 99.6 %, its G "
           "being 2^30). Rendered as a long run: `texsim sweep clipmap --log2-virtual 15 "
           "--settings 10` (docs/clipmap.md).\n\n";
  }
  if (stem == "nurbs") {
    return "### NURBS texturing: the tau unit's grid (claims 4-6)\n\n"
           "The wave map (u = s + 0.05 sin(2 pi 1.5 t), v alike) on 256 x 256 texels, as a render "
           "loads it into the tau unit (the map sampled at the grid's nodes, rounded to "
           "TexCoord), golden against the functional map on 200 000 random (s, t) and screen "
           "derivatives (a quarter texel to 64 texels a pixel); |delta (u, v)| in texels, lambda "
           "in levels. The affine rows sample where the unit's 12-bit weight fractions are exact: "
           "an affine map comes out exact in either interpolation (the lambda error there is the "
           "log2 table's); the last one samples anywhere (the weights' truncation). At 1 cell the "
           "spline's stencil holds two extrapolated nodes, a line: it is the linear grid; at 2 "
           "cells neither grid resolves the wave's 1.5 periods. rtl = golden on the first 4000 "
           "samples of each row; cycles per sample at rtl once the grid is loaded.\n\n" +
           read_file(data / "nurbs_tau.md") +
           "\n### NURBS texturing: the composition orders (claims 15-18)\n\n"
           "scenes/nurbs_orders.json's first sphere alone, in the middle of the frame (wave tau, "
           "8 x 8 spline grid, its own tessellation, DC 12), in each order against the same kind "
           "of reference, and in order pc with twice the grid's cells (16 x 16): what order pc "
           "loses to tc here is the 8 x 8 tau grid's error. Errors of golden's frame; unit cycles "
           "at rtl, rendered with "
           "the unit-by-unit check against golden (rtl = golden: every pixel and every unit's "
           "outputs, requests and counters).\n\n" +
           read_file(data / "nurbs_orders.md") + "\n";
  }
  if (stem == "volume") {
    return "### Volume rendering: the patent's two data sets on four chips\n\n"
           "Rays along z, one a voxel column, i fastest (step 1: one resample per voxel, the "
           "patent's case), each data set in four slabs along x with their ghost planes "
           "(docs/volume.md), the time the slowest chip's at 30 ns an access and one more on a "
           "page fault. RGBA: each chip resamples the four components of its slab in value mode "
           "(as many accesses a chip as one component of the whole set a chip).\n\n" +
           read_file(data / "volume_patent.md") + "\n";
  }
  return "";
}

std::string document(const SweepAllArgs& args, const fs::path& data, const std::string& scene,
                     const RunContext& run) {
  const std::string rel = data.filename().string();
  std::string doc = fmt::format(
      "# What accuracy costs\n\n"
      "{} Each block's own document says how to read its figures; this one puts them side "
      "by side. The tables are also in `{}/` as CSV, which `scripts/plot_accuracy.py` plots.\n\n"
      "Every figure is marked by how it was obtained: a column's header names its mark, a "
      "cell obtained otherwise names its own (the CSV files hold the figures alone).\n\n{}\n"
      "## Model levels: what fidelity costs in simulation time\n\n"
      "One workload per block through every model level (`texsim levels`): transactions per "
      "second and the ratio to golden. Every level but ideal is compared with golden bit for "
      "bit (= golden). rtl is Verilator with one thread; rtl-fst the same with every signal "
      "traced to an FST file; rtl-threads the block verilated with `--threads 2`; icarus the "
      "same RTL under Icarus Verilog.\n\n{}\n"
      "## The default scene at every engine\n\n`{}`, whole render (front end, textures, units), "
      "`texsim render --engine E`; hls and rtl compared with golden by their frames, pixel for "
      "pixel:\n\n{}\n",
      provenance(args, run), rel, marks_legend(), read_file(data / "levels.md"),
      display_path(scene), read_file(data / "scene_levels.md"));
  for (const Section& s : kSections) {
    doc +=
        fmt::format("## {}\n\n{} Reading: [{}]({}).\n\n{}\n![{}]({}/{}.png)\n\n", s.title, s.about,
                    s.doc, s.doc, read_file(data / (s.stem + ".md")), s.title, rel, s.stem);
    doc += section_tail(s.stem, data);
  }
  doc +=
      "## CCC decoder and low-cost unit (000 §3-4)\n\nNo width settings: the decoder is "
      "exact (a CLUT look-up) and the low-cost unit's weights are the 8 bits §4 gives them. "
      "Their figures: [ccc.md](ccc.md).\n";
  return doc;
}

}  // namespace

void sweep_all(const SweepAllArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  RunContext run;
  run.load_start = load_average();
  const fs::path data = fs::path(args.out_dir) / "accuracy";
  fs::create_directories(data);
  const std::string scene =
      args.scene.empty() ? std::string(TMU_SOURCE_DIR) + "/scenes/default.json" : args.scene;

  std::vector<BlockLevels> levels;
  for (const std::string& block : kLevelBlocks) {
    levels.push_back(measure_levels(block, args.level_count, 1, std::cout));
  }
  levels_table(levels).print((data / "levels.md").string());
  const fs::path renders = fs::temp_directory_path() / "tmu_sweep_all_renders";
  scene_levels_table(measure_scene_levels(scene, renders.string(), std::cout))
      .print((data / "scene_levels.md").string());
  fs::remove_all(renders);

  run_block_sweeps(args, data);

  const std::string plot =
      fmt::format("{} {}/scripts/plot_accuracy.py {}", args.python, TMU_SOURCE_DIR, data.string());
  if (std::system(plot.c_str()) != 0) {
    throw std::runtime_error("sweep all: the plots failed: " + plot);
  }
  run.minutes =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60;
  run.load_end = load_average();
  const std::string path = (fs::path(args.out_dir) / "accuracy.md").string();
  write_file_atomically(path, document(args, data, scene, run));
  fmt::print("wrote {}\n", path);
}

}  // namespace tmu::texsim
