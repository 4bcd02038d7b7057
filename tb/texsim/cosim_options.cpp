#include "texsim/cosim_options.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstdio>
#include <sstream>

#include "formats/formats.hpp"
#include "texsim/texram_options.hpp"

namespace tmu::texsim {

// The options as parsed; finish() turns them into a CosimRequest.
struct CosimArgs {
  std::string block;
  tb::CosimOptions cosim;
  tb::BlockOptions block_options;
  std::string engines = "hls,rtl";
  // trilinear overrides of the seed's environment; empty: drawn from the seed
  std::string config, channel, filter, border_u, border_v, border_colour, combine, constant, widths;
  std::optional<int> log2_w, log2_h;
  // footprint overrides; empty: drawn from the seed
  std::optional<int> max_probes;
  std::string q_rule, fp_widths;
  std::string encoder;                // normal_encoder: S,E,M
  std::string coord_tables;           // coord_gen: A,W
  std::string fractal = "pipelined";  // turbulence: pipelined | shared
  std::string volume_mode;            // volume: value | raw; empty: drawn
};

namespace {

// "--widths 6,6,6 and --widths 4,4,4": the options of a block's variants (rtl/blocks.cmake).
std::string variant_options(const std::string& block) {
  std::string out;
  for (const tb::BlockVariant& v : tb::block_variants()) {
    if (v.block != block || v.options.empty()) continue;
    out += (out.empty() ? "" : ", ") + v.options;
  }
  return out.empty() ? "none" : out;
}

}  // namespace

std::shared_ptr<CosimArgs> add_cosim_options(CLI::App& app) {
  CLI::App* cmd = &app;
  auto args = std::make_shared<CosimArgs>();

  cmd->add_option("block", args->block, "Block to co-simulate")->required();
  cmd->add_option("--seed", args->cosim.seed, "Seed of the random stimulus and stalls")
      ->capture_default_str();
  cmd->add_option("--count", args->cosim.count, "Random transactions after the directed ones")
      ->capture_default_str();
  cmd->add_option("--engines", args->engines,
                  "Levels compared against golden, comma separated: hls (SystemC), rtl "
                  "(Verilator), icarus (the rtl under Icarus Verilog), ideal, rtl-threads, as "
                  "the block has them (an unknown level is an error that lists the block's)")
      ->capture_default_str();
  cmd->add_option("--vectors", args->cosim.vectors_in,
                  "Replay a vector file (CSV) instead of directed + random")
      ->check(CLI::ExistingFile);
  cmd->add_option("--save-vectors", args->cosim.vectors_out,
                  "Write the stimulus that was run to a vector file");
  cmd->add_flag(
      "--no-directed", [args](int64_t) { args->cosim.directed = false; },
      "Skip the directed vectors");
  cmd->add_option("--in-idle", args->cosim.in_idle,
                  "Probability of an idle cycle before each input item")
      ->check(CLI::Range(0.0, 0.95))
      ->capture_default_str();
  cmd->add_option("--out-stall", args->cosim.out_stall,
                  "Probability of output ready low in a cycle")
      ->check(CLI::Range(0.0, 0.95))
      ->capture_default_str();
  cmd->add_flag(
      "--no-x-check", [args](int64_t) { args->cosim.x_check = false; },
      "Skip the second rtl run with other random initial values");
  cmd->add_option("--wave-dir", args->cosim.wave_dir,
                  "Where a mismatch waveform (FST + GTKWave file) goes")
      ->capture_default_str();
  cmd->add_option("--wave-before", args->cosim.wave_before,
                  "Cycles of waveform before the mismatch")
      ->capture_default_str();
  cmd->add_option("--wave-after", args->cosim.wave_after, "Cycles of waveform after the mismatch")
      ->capture_default_str();
  cmd->add_option("--inject-fault", args->cosim.inject_fault,
                  "Flip one bit of output N of every engine, to see the scoreboard catch it");
  cmd->add_option("--texture", args->block_options.texture,
                  "ccc_cache_bilinear: a texture (.ccc) instead of random ones")
      ->check(CLI::ExistingFile);
  cmd->add_option("--mip-log2-w", args->block_options.mip_log2_w,
                  "mipgen: log2 width 0..10 of every frame format (default: drawn per format)")
      ->check(CLI::Range(0, 10));
  cmd->add_option("--mip-log2-h", args->block_options.mip_log2_h,
                  "mipgen: log2 height 0..10 of every frame format (default: drawn per format)")
      ->check(CLI::Range(0, 10));
  cmd->add_option(
         "--mip-interlaced", args->block_options.mip_interlaced,
         "mipgen: every frame interlaced (1) or progressive (0) (default: drawn per format)")
      ->check(CLI::Range(0, 1));
  cmd->add_option("--map-latency", args->block_options.dfl_map_latency,
                  "deflect: cycles from a map block request to its response")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--map-jitter", args->block_options.dfl_map_jitter,
                  "deflect: up to this many extra cycles per map request, drawn from the seed")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--encoder", args->encoder,
                  "normal_encoder: seed-table bits S, angle-table exponent levels E and mantissa "
                  "bits M (default 7,4,5; rtl variants: " +
                      variant_options("normal_encoder") + ")");
  cmd->add_option("--coord-tables", args->coord_tables,
                  "coord_gen: the tables' grid bits A (a 2^A x 2^(A-1) grid) and entry bits W "
                  "(default 9,10; rtl variants: " +
                      variant_options("coord_gen") + ")");
  cmd->add_option("--fractal", args->fractal,
                  "turbulence, material: four noise units, one sample per clock (pipelined), or "
                  "one noise unit for the four octaves, one sample per 4 clocks (shared)")
      ->check(CLI::IsMember({"pipelined", "shared"}))
      ->capture_default_str();
  cmd->add_option("--chip-workload", args->block_options.chip_workload,
                  "texram_chip: random items from scan lines of one program instead of random "
                  "programs: texture (a one-plane map), detail (the map with a detail map), "
                  "extreme (texture and reflectance maps each with a detail map, then a cube "
                  "environment map)")
      ->check(CLI::IsMember({"texture", "detail", "extreme"}));
  cmd->add_flag(
      "--no-lookahead", [args](int64_t) { args->block_options.lookahead = false; },
      "ccc_cache_bilinear: the neighbour prefetch off (default: on, drawn for later batches)");
  // trilinear: each option given overrides the environment drawn from the seed.
  auto* tri =
      cmd->add_option_group("trilinear", "trilinear: override the environment drawn from the seed");
  tri->add_option("--config", args->config, "luminance | index | rgba | single | ccc")
      ->check(CLI::IsMember({"luminance", "index", "rgba", "single", "ccc"}));
  tri->add_option("--channel", args->channel, "single: r | g | b | a")
      ->check(CLI::IsMember({"r", "g", "b", "a"}));
  tri->add_option("--filter", args->filter, "nearest | bilinear | trilinear")
      ->check(CLI::IsMember({"nearest", "bilinear", "trilinear"}));
  tri->add_option("--border-u", args->border_u, "wrap | clamp | border | mirror");
  tri->add_option("--border-v", args->border_v, "wrap | clamp | border | mirror");
  tri->add_option("--border-colour", args->border_colour, "0xRRGGBBAA");
  tri->add_option("--combine", args->combine, "one | constant | shade")
      ->check(CLI::IsMember({"one", "constant", "shade"}));
  tri->add_option("--constant", args->constant, "k_T, 0xRRGGBBAA");
  tri->add_option("--log2-w", args->log2_w, "log2 of the texture width, 0..10")
      ->check(CLI::Range(0, 10));
  tri->add_option("--log2-h", args->log2_h, "log2 of the texture height, 0..10")
      ->check(CLI::Range(0, 10));
  tri->add_option("--pattern", args->block_options.tri_pattern,
                  "texture content: gradient | checker | noise | smooth | random")
      ->check(CLI::IsMember({"gradient", "checker", "noise", "smooth", "random"}));
  tri->add_option("--image", args->block_options.tri_image, "texture content: an image file")
      ->check(CLI::ExistingFile);
  tri->add_option(
      "--widths", args->widths,
      "internal widths S,W,L (default 8,8,8; rtl variants: " + variant_options("trilinear") + ")");
  // footprint: the trilinear options above, and the setup's.
  auto* fp = cmd->add_option_group(
      "footprint", "footprint: the trilinear options above, and the setup's (else from the seed)");
  fp->add_option("--max-probes", args->max_probes,
                 "at most N probes per fragment: 1 | 2 | 4 | 8 | 16")
      ->check(CLI::IsMember({1, 2, 4, 8, 16}));
  fp->add_option("--q-rule", args->q_rule,
                 "the edge length q: heights (of the parallelogram) | sides (the shorter)")
      ->check(CLI::IsMember({"heights", "sides"}));
  fp->add_option("--fp-widths", args->fp_widths,
                 "setup widths D,T,F: derivative, log2 table and log fraction bits (default "
                 "12,7,8; rtl variants: " +
                     variant_options("footprint") + ")");

  auto* vol = cmd->add_option_group("volume", "volume: the mode and the rays");
  vol->add_option("--volume-mode", args->volume_mode,
                  "the mode of every volume drawn: value (2 accesses a resample) | raw (8, with "
                  "the gradient); default drawn per volume")
      ->check(CLI::IsMember({"value", "raw"}));
  vol->add_option("--volume-rays", args->block_options.vol_rays,
                  "run a figure's ray set through a 64 x 128 x 128 volume instead of the "
                  "directed and random rays (--count rays, in order; docs/volume.md): z | x | "
                  "oblique")
      ->check(CLI::IsMember({"z", "x", "oblique"}));

  auto* video = cmd->add_option_group("video_unit", "video_unit: the rows and a figure's workload");
  video
      ->add_option("--video-cells", args->block_options.video_cells,
                   "cells of a row buffer: 8 (the block's short rows) or 512 (a page, the chip's "
                   "rows; rtl variant page)")
      ->check(CLI::IsMember({8, 512}))
      ->capture_default_str();
  video
      ->add_option("--video-workload", args->block_options.video_workload,
                   "instead of the directed and random items, two frames of a 512 x 512 video "
                   "at 30 frames per second, the sampler wanting every cycle, L = 64 "
                   "(docs/video.md's figure): 1p | 4p | 1i | 4i (planes, progressive or "
                   "interlaced)")
      ->check(CLI::IsMember({"1p", "4p", "1i", "4i"}));

  return args;
}

CosimRequest finish(const CosimArgs& in) {
  CosimArgs copy = in;
  CosimArgs* args = &copy;
  args->cosim.engines.clear();
  std::stringstream ss(args->engines);
  for (std::string e; std::getline(ss, e, ',');) {
    if (e != "hls" && e != "rtl" && e != "icarus")
      throw CLI::ValidationError("--engines", "unknown engine '" + e + "'");
    args->cosim.engines.push_back(e);
  }
  args->block_options.seed = args->cosim.seed;
  tb::BlockOptions& b = args->block_options;
  if (!args->config.empty()) b.tri_kind = texram::parse_texel_kind(args->config);
  if (!args->channel.empty())
    b.tri_single_channel = static_cast<int>(std::string("rgba").find(args->channel));
  if (!args->filter.empty()) b.tri_filter = texram::parse_filter(args->filter);
  if (!args->border_u.empty()) b.tri_border_u = parse_border_option("--border-u", args->border_u);
  if (!args->border_v.empty()) b.tri_border_v = parse_border_option("--border-v", args->border_v);
  if (!args->border_colour.empty())
    b.tri_border_rgba = parse_rgba_option("--border-colour", args->border_colour);
  if (!args->combine.empty()) b.tri_combine = texram::parse_combine(args->combine);
  if (!args->constant.empty())
    b.tri_constant_rgba = parse_rgba_option("--constant", args->constant);
  if (!args->widths.empty()) b.tri_widths = parse_widths_option("--widths", args->widths);
  b.tri_log2_w = args->log2_w;
  b.tri_log2_h = args->log2_h;
  if (args->max_probes)
    b.fp_log2_max_probes = std::countr_zero(static_cast<unsigned>(*args->max_probes));
  if (!args->q_rule.empty()) b.fp_q_rule = footprint::parse_q_rule(args->q_rule);
  if (!args->fp_widths.empty()) {
    footprint::Widths& w = b.fp_widths;
    if (std::sscanf(args->fp_widths.c_str(), "%d,%d,%d", &w.deriv_bits, &w.table_bits,
                    &w.log_frac) != 3 ||
        w.deriv_bits < 6 || w.deriv_bits > 24 || w.table_bits < 1 || w.table_bits > 10 ||
        w.log_frac < 1 || w.log_frac > 12) {
      throw CLI::ValidationError(
          "--fp-widths",
          "'" + args->fp_widths + "' is not D,T,F with D 6..24, T 1..10, F 1..12 like 12,7,8");
    }
  }
  if (!args->encoder.empty()) {
    deflect::EncoderConfig& e = b.encoder;
    if (std::sscanf(args->encoder.c_str(), "%d,%d,%d", &e.seed_bits, &e.lut_exp, &e.lut_mant) !=
            3 ||
        e.seed_bits < 2 || e.seed_bits > 12 || e.lut_exp < 1 || e.lut_exp > 8 || e.lut_mant < 2 ||
        e.lut_mant > 10) {
      throw CLI::ValidationError(
          "--encoder",
          "'" + args->encoder + "' is not S,E,M with S 2..12, E 1..8, M 2..10 like 7,4,5");
    }
  }
  if (!args->coord_tables.empty()) {
    deflect::TableConfig& t = b.coord_tables;
    int phi_bits = 0;
    if (std::sscanf(args->coord_tables.c_str(), "%d,%d", &phi_bits, &t.value_bits) != 2 ||
        phi_bits < 6 || phi_bits > formats::kSpherePhi.width() || t.value_bits < 8 ||
        t.value_bits > formats::kCoordValue.width()) {
      throw CLI::ValidationError(
          "--coord-tables",
          "'" + args->coord_tables + "' is not A,W with A 6..9, W 8..10 like 9,10");
    }
    t.grid = deflect::SphereGrid{phi_bits};
  }
  b.fractal_shared = args->fractal == "shared";
  if (!args->volume_mode.empty()) b.vol_mode = args->volume_mode == "raw" ? 1 : 0;
  return {args->block, args->cosim, args->block_options};
}

CosimRequest parse_cosim_line(const std::string& line) {
  CLI::App app("cosim");
  const auto args = add_cosim_options(app);
  app.parse(line, false);
  return finish(*args);
}

}  // namespace tmu::texsim
