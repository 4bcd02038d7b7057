// `texsim ccc`: the CCC codec from the command line: encode, decode through any engine, and
// the round trip of an image through golden and rtl with the bit-exact verdict.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_block.hpp"
#include "blocks/ccc_decoder/ccc_decoder_block.hpp"
#include "ccc/ccc_decoder.hpp"
#include "ccc/ccc_encoder.hpp"
#include "common/error.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string rate(double n, double s) {
  return s > 0 ? fmt::format("{:.2f} M texels/s", n / s / 1e6) : "-";
}

ccc::Texture encode_file(const std::string& in, ImageRgb8* image_out) {
  ImageRgb8 image = read_image(in);
  const auto t0 = std::chrono::steady_clock::now();
  ccc::Texture tex = ccc::encode(image);
  const double t = seconds_since(t0);
  const ccc::EncodeReport rep = ccc::report_encoding(image, tex);
  fmt::print(
      "encoded {} ({}x{}) in {:.3f} s: PSNR {:.2f} dB (unquantized two-colour ideal {:.2f} dB), "
      "{:.3f} bits per texel\n",
      in, image.width, image.height, t, rep.psnr_encoded, rep.psnr_ideal, rep.bits_per_texel);
  if (image_out) *image_out = std::move(image);
  return tex;
}

// Decodes through `level`; prints the throughput. Returns the image.
ImageRgb8 decode_through(const ccc::Texture& tex, const std::string& level) {
  const auto engine = tb::CccDecoderBlock().engine(level);
  tb::RunResult run;
  const ImageRgb8 img = tb::decode_with_engine(tex, *engine, &run);
  const double texels = static_cast<double>(img.pixels.size());
  fmt::print("  {:<6} decoded {} texels in {:.3f} s ({}){}\n", level, img.pixels.size(),
             run.seconds, rate(texels, run.seconds),
             run.cycles ? fmt::format(", {} cycles", run.cycles) : "");
  return img;
}

// Compares two decodes texel for texel; prints the verdict; returns true on a match.
bool check(const ImageRgb8& ref, const ImageRgb8& got, const std::string& ref_name,
           const std::string& got_name) {
  size_t differ = 0;
  std::string first;
  for (int y = 0; y < ref.height; ++y) {
    for (int x = 0; x < ref.width; ++x) {
      const Rgb8 a = ref.at(x, y), b = got.at(x, y);
      if (a == b) continue;
      if (++differ <= 5) {
        first += fmt::format("    texel ({}, {}): {} 0x{:06x}, {} 0x{:06x}\n", x, y, ref_name,
                             pack_rgb(a), got_name, pack_rgb(b));
      }
    }
  }
  if (differ == 0) {
    fmt::print("MATCH: {} = {}, all {} texels bit-exact\n", ref_name, got_name, ref.pixels.size());
    return true;
  }
  fmt::print("MISMATCH: {} of {} texels differ between {} and {}; first ones:\n{}", differ,
             ref.pixels.size(), ref_name, got_name, first);
  return false;
}

// Magnifies the texture 2x through the low-cost unit (cache + bilinear) on golden and rtl;
// prints the verdict and the cache statistics; returns the rtl image, or nothing on a mismatch.
std::optional<ImageRgb8> magnify_through_unit(const std::string& ccc_path,
                                              const ccc::Texture& tex) {
  tb::BlockOptions opt;
  opt.texture = ccc_path;
  const tb::CccCacheBilinearBlock block(opt);
  const uint32_t w = 2 * tex.width, h = 2 * tex.height;
  std::vector<tb::Txn> items = block.setup_items();
  for (const tb::Txn& t : tb::bilinear_resample_items(tex, w, h)) items.push_back(t);
  const tb::RunResult golden = block.engine("golden")->run(items, tb::RunOptions{});
  const tb::RunResult rtl = block.engine("rtl")->run(items, tb::RunOptions{});
  if (!rtl.error.empty())
    throw std::runtime_error("rtl run of the low-cost unit failed: " + rtl.error);
  auto counter = [&](const char* name) {
    return tb::counter_value(golden.counters, name).value_or(0);
  };
  const uint64_t hits = counter("hits"), misses = counter("misses");
  fmt::print(
      "low-cost unit (cache + bilinear), 2x magnification to {}x{}: cache hits {}, misses {}, "
      "prefetches {} (hit rate {:.1f} %); rtl {} cycles, {:.2f} cycles per pixel\n",
      w, h, hits, misses, counter("prefetches"),
      100.0 * static_cast<double>(hits) / static_cast<double>(std::max<uint64_t>(hits + misses, 1)),
      rtl.cycles, static_cast<double>(rtl.cycles) / (double{1} * w * h));
  if (golden.outputs != rtl.outputs || golden.counters != rtl.counters) {
    size_t differ = 0;
    for (size_t i = 0; i < std::min(golden.outputs.size(), rtl.outputs.size()); ++i) {
      differ += golden.outputs[i] != rtl.outputs[i];
    }
    fmt::print(
        "MISMATCH: {} of {} pixels differ (or the counters do); reproduce with "
        "texsim cosim ccc_cache_bilinear --texture {}\n",
        differ, size_t{w} * h, ccc_path);
    return std::nullopt;
  }
  fmt::print("MATCH: golden = rtl, all {} pixels and the cache counters bit-exact\n",
             size_t{w} * h);
  ImageRgb8 img(static_cast<int>(w), static_cast<int>(h));
  for (size_t i = 0; i < img.pixels.size(); ++i)
    img.pixels[i] = unpack_rgb(static_cast<uint32_t>(rtl.outputs[i].f[0]));
  return img;
}

}  // namespace

void add_ccc_command(CLI::App& app, ExitCode& exit_code) {
  auto* ccc =
      app.add_subcommand("ccc", "Colour cell compression (000 §3): encode, decode, round trip");
  ccc->require_subcommand(1);

  {
    auto* cmd = ccc->add_subcommand("encode",
                                    "Encode an image (any format OpenImageIO reads) to .ccc;\n"
                                    "prints PSNR against the input, bits per texel and time");
    auto in = std::make_shared<std::string>(), out = std::make_shared<std::string>();
    cmd->add_option("input", *in, "Input image")->required()->check(CLI::ExistingFile);
    cmd->add_option("output", *out, "Output .ccc file (written atomically)")->required();
    cmd->callback([in, out] { ccc::write_ccc(*out, encode_file(*in, nullptr)); });
  }
  {
    auto* cmd = ccc->add_subcommand("decode",
                                    "Decode a .ccc file to an image through one engine's decoder");
    auto in = std::make_shared<std::string>(), out = std::make_shared<std::string>();
    auto engine = std::make_shared<std::string>("golden"),
         check_against = std::make_shared<std::string>();
    cmd->add_option("input", *in, "Input .ccc file")->required()->check(CLI::ExistingFile);
    cmd->add_option("output", *out, "Output image (format from the extension, written atomically)")
        ->required();
    cmd->add_option("--engine", *engine, "golden | hls | rtl")
        ->check(CLI::IsMember(kCosimEngines))
        ->capture_default_str();
    cmd->add_option("--check", *check_against,
                    "Also decode with this engine and compare every texel bit for bit")
        ->check(CLI::IsMember(kCosimEngines));
    cmd->callback([=, &exit_code] {
      const ccc::Texture tex = ccc::read_ccc(*in);
      const ImageRgb8 img = decode_through(tex, *engine);
      if (!check_against->empty() &&
          !check(decode_through(tex, *check_against), img, *check_against, *engine)) {
        exit_code.value = 1;
        return;  // no output in place of a wrong one
      }
      write_image(*out, img);
      fmt::print("wrote {}\n", *out);
    });
  }
  {
    auto* cmd = ccc->add_subcommand(
        "roundtrip",
        "Encode an image, decode it through golden and rtl, and check they agree bit for bit;\n"
        "then magnify it 2x through the low-cost unit (cache + bilinear) on golden and rtl.\n"
        "Writes OUT/<name>.ccc, OUT/<name>_decoded.png, OUT/<name>_magnified.png");
    auto in = std::make_shared<std::string>(), out_dir = std::make_shared<std::string>("out");
    cmd->add_option("input", *in, "Input image")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", *out_dir, "Output directory")->capture_default_str();
    cmd->callback([=, &exit_code] {
      std::filesystem::create_directories(*out_dir);
      const std::string stem = std::filesystem::path(*in).stem().string();
      const std::string ccc_path = (std::filesystem::path(*out_dir) / (stem + ".ccc")).string();
      const ccc::Texture tex = encode_file(*in, nullptr);
      ccc::write_ccc(ccc_path, tex);
      const ImageRgb8 golden = decode_through(tex, "golden");
      const ImageRgb8 rtl = decode_through(tex, "rtl");
      if (!check(golden, rtl, "golden", "rtl")) {
        exit_code.value = 1;
        return;
      }
      const std::optional<ImageRgb8> magnified = magnify_through_unit(ccc_path, tex);
      if (!magnified) {
        exit_code.value = 1;
        return;
      }
      const auto dir = std::filesystem::path(*out_dir);
      write_image((dir / (stem + "_decoded.png")).string(), rtl);
      write_image((dir / (stem + "_magnified.png")).string(), *magnified);
      fmt::print("wrote {}, {}_decoded.png and {}_magnified.png in {}\n", ccc_path, stem, stem,
                 *out_dir);
    });
  }
}

}  // namespace tmu::texsim
