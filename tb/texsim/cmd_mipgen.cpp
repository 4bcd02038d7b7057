// `texsim mipgen`: an image through the TEXRAM mipmap generator (000 §12) of one engine, once
// per plane; the writes go to a bank image, every level is read back from the banks through
// the layout (Geometry::cell) and written as OUTDIR/level_<l>.png.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "blocks/mipgen/mipgen_block.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "formats/formats.hpp"
#include "texram/layout.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"
#include "texram/texture.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {
namespace {

constexpr std::array<const char*, 3> kPlaneNames{"R", "G", "B"};

uint8_t channel(const Rgb8& c, int plane) { return plane == 0 ? c.r : plane == 1 ? c.g : c.b; }

// The generator's writes for one plane through `engine`: `items` are the plane's format and
// its `texels` texels; prints the run.
std::vector<tb::Txn> run_engine(const std::string& engine, const std::vector<tb::Txn>& items,
                                size_t texels, const std::string& what) {
  const tb::RunResult r = tb::MipgenBlock().engine(engine)->run(items, tb::RunOptions{});
  if (!r.error.empty()) throw std::runtime_error(engine + " mipgen run failed: " + r.error);
  fmt::print("  {:<6} {}: {} texels -> {} writes in {:.3f} s{}\n", engine, what, texels,
             r.outputs.size(), r.seconds, r.cycles ? fmt::format(", {} cycles", r.cycles) : "");
  return r.outputs;
}

// Compares two engines' writes one by one; prints the first mismatches; true on a match.
bool same_writes(const std::vector<tb::Txn>& ref, const std::vector<tb::Txn>& got,
                 const std::string& ref_name, const std::string& got_name,
                 const std::string& what) {
  size_t differ = ref.size() > got.size() ? ref.size() - got.size() : got.size() - ref.size();
  std::string first;
  auto text = [](const tb::Txn& t) {
    const texram::CellWrite w = tb::mipgen_txn_write(t);
    return fmt::format("level {} ({}, {}) = {} -> bank {} address {}", w.level, w.x, w.y, w.value,
                       w.cell.bank, w.cell.address);
  };
  for (size_t i = 0; i < std::min(ref.size(), got.size()); ++i) {
    if (ref[i] == got[i]) continue;
    if (++differ <= 5) {
      first += fmt::format("    write {}: {} {}\n    {:>{}} {} {}\n", i, ref_name, text(ref[i]), "",
                           fmt::format("{}", i).size() + 7, got_name, text(got[i]));
    }
  }
  if (differ == 0) return true;
  fmt::print("MISMATCH {}: {} of {} writes differ between {} and {} ({} and {} writes); first:\n{}",
             what, differ, std::max(ref.size(), got.size()), ref_name, got_name, ref.size(),
             got.size(), first);
  return false;
}

}  // namespace

void add_mipgen_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "mipgen",
      "Real-time mipmap generation (000 §12, Fig. 14): stream an image's texels through the\n"
      "generator of one engine (once per plane: R, G, B; one plane for a grey image), store its\n"
      "bank writes, read every level back from the banks through the layout, and write\n"
      "OUTDIR/level_<l>.png. The image must have power-of-two sides up to 1024.");
  struct Args {
    std::string in, out_dir, engine = "golden", check;
    bool interlaced = false, luminance = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("input", args->in, "Input image")->required()->check(CLI::ExistingFile);
  cmd->add_option("outdir", args->out_dir, "Output directory (created)")->required();
  cmd->add_option("--engine", args->engine, "golden | hls | rtl")
      ->check(CLI::IsMember(kCosimEngines))
      ->capture_default_str();
  cmd->add_option("--check", args->check,
                  "Also run this engine and compare every write bit for bit")
      ->check(CLI::IsMember(kCosimEngines));
  cmd->add_flag("--interlaced", args->interlaced,
                "Interlaced source: field 1 (even lines), then field 2 (odd lines, each texel\n"
                "with the one above it, read back from the banks)");
  cmd->add_flag("--luminance", args->luminance,
                "Convert a colour image to grey, (77 R + 150 G + 29 B + 128) >> 8: one plane");
  cmd->callback([args, &exit_code] {
    const ImageRgb8 image = read_image(args->in);
    const auto w = static_cast<uint32_t>(image.width), h = static_cast<uint32_t>(image.height);
    const uint32_t max_side = 1u << formats::kMaxMipLog2;
    if (!std::has_single_bit(w) || !std::has_single_bit(h) || w > max_side || h > max_side) {
      throw InputError(args->in, "size",
                       fmt::format("{}x{} texels; the mipmap generator takes power-of-two sides "
                                   "up to {}",
                                   w, h, max_side));
    }
    const int lw = std::countr_zero(w), lh = std::countr_zero(h);
    const bool grey =
        args->luminance || std::all_of(image.pixels.begin(), image.pixels.end(),
                                       [](const Rgb8& c) { return c.r == c.g && c.g == c.b; });
    const int generated = grey ? 1 : 3;  // planes run through the generator
    const int planes = grey ? 1 : formats::kPlanes;
    const texram::Geometry geometry(lw, lh, planes);
    fmt::print("mipgen {}: {}x{} texels, {} levels, {}, {}, engine {}\n", args->in, w, h,
               geometry.levels(),
               grey ? (args->luminance ? "luminance (one plane)" : "grey (one plane)")
                    : "colour (planes R, G, B of a four-plane texture)",
               args->interlaced ? "interlaced" : "progressive", args->engine);

    texram::BankMemory banks(geometry);
    std::vector<texram::Pyramid8> expected;
    bool match = true;
    for (int p = 0; p < generated; ++p) {
      texram::Level8 level0(w, h);
      for (size_t i = 0; i < image.pixels.size(); ++i) {
        const Rgb8& c = image.pixels[i];
        level0.texels[i] = args->luminance ? texram::luma(c) : channel(c, p);
      }
      const texram::MipgenConfig cfg{lw, lh, args->interlaced, planes, p};
      const std::vector<tb::Txn> items = tb::mipgen_items(cfg, level0);
      const std::string what =
          grey ? "plane" : fmt::format("plane {}", kPlaneNames[static_cast<size_t>(p)]);
      const size_t texels = level0.texels.size();
      const std::vector<tb::Txn> writes = run_engine(args->engine, items, texels, what);
      if (!args->check.empty()) {
        const std::vector<tb::Txn> ref = run_engine(args->check, items, texels, what);
        if (!same_writes(ref, writes, args->check, args->engine, what)) {
          match = false;
          continue;
        }
      }
      try {
        for (const tb::Txn& t : writes) banks.write(tb::mipgen_txn_write(t));
      } catch (const std::out_of_range& e) {
        fmt::print("MISMATCH {}: {}\n", what, e.what());
        match = false;
        continue;
      }
      expected.push_back(texram::build_pyramid(level0));
    }
    if (!match) {
      exit_code.value = 1;
      return;  // no output in place of a wrong one
    }
    if (!args->check.empty()) {
      fmt::print("MATCH: {} = {}, every write of every plane bit-exact\n", args->engine,
                 args->check);
    }

    // Every level of every plane read back from the banks through the layout.
    std::vector<ImageRgb8> levels;
    try {
      for (int l = 0; l < geometry.levels(); ++l) {
        ImageRgb8 img(static_cast<int>(geometry.texel_width(l)),
                      static_cast<int>(geometry.texel_height(l)));
        for (int p = 0; p < generated; ++p) {
          const texram::Level8 got = banks.read_level(l, p);
          if (got != expected[static_cast<size_t>(p)][static_cast<size_t>(l)]) {
            throw std::runtime_error(
                fmt::format("level {} of plane {} read back from the banks "
                            "differs from the box-filter pyramid",
                            l, p));
          }
          for (size_t i = 0; i < img.pixels.size(); ++i) {
            Rgb8& c = img.pixels[i];
            if (grey) c = {got.texels[i], got.texels[i], got.texels[i]};
            if (p == 0 && !grey) c.r = got.texels[i];
            if (p == 1) c.g = got.texels[i];
            if (p == 2) c.b = got.texels[i];
          }
        }
        levels.push_back(std::move(img));
      }
      for (int p = 0; p < generated; ++p) {
        if (const size_t n = banks.cells_not_written_once(p); n != 0) {
          throw std::runtime_error(
              fmt::format("{} cells of plane {} were not written exactly once", n, p));
        }
      }
    } catch (const std::runtime_error& e) {
      fmt::print("MISMATCH: {}\n", e.what());
      exit_code.value = 1;
      return;
    }
    fmt::print(
        "read back through the bank layout: every level = the box-filter pyramid, every cell "
        "(replicas included) written once\n");

    std::filesystem::create_directories(args->out_dir);
    const std::filesystem::path dir(args->out_dir);
    for (size_t l = 0; l < levels.size(); ++l) {
      const std::string path = (dir / fmt::format("level_{}.png", l)).string();
      write_image(path, levels[l]);
      fmt::print("  level {:>2}  {:>4} x {:<4}  {}\n", l, levels[l].width, levels[l].height, path);
    }
  });
}

}  // namespace tmu::texsim
