// `texsim terrain`: the clip-map fly-over's virtual texture (golden/clipmap/terrain.hpp) as a
// tiled, mip-mapped file, made by OpenImageIO's maketx from the picture, which the clip-map's
// tile manager reads tile by tile (docs/clipmap.md).
#include <fmt/format.h>

#include <chrono>
#include <memory>

#include "clipmap/terrain.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {

void add_terrain_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "terrain",
      "Write a terrain-like picture of 2^LOG2 x 2^LOG2 texels (the noise unit's fractal sums as "
      "heights, coloured and shaded) as a tiled, mip-mapped file made by maketx (box filter): "
      "the clip-map fly-over's virtual texture");
  struct Args {
    std::string out;
    int log2 = 10, tile = 64;
    uint32_t seed = 1;
    bool keep_picture = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("output", a->out, "The tiled mipmap (.tx); the picture goes beside it as .tif")
      ->required();
  cmd->add_option("--log2", a->log2, "log2 of the side: 10 is 1024 texels, 15 the patent's 32k")
      ->check(CLI::Range(2, 15))
      ->capture_default_str();
  cmd->add_option("--tile", a->tile, "the file's tile side in texels (maketx --tile)")
      ->check(CLI::Range(8, 1024))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "the terrain's seed")->capture_default_str();
  cmd->add_flag("--keep-picture", a->keep_picture, "keep the .tif the file is made from");
  cmd->callback([a, &exit_code] {
    const auto start = std::chrono::steady_clock::now();
    clipmap::write_terrain_mipmap(a->out, a->log2, a->seed, a->tile, a->keep_picture);
    fmt::print("wrote {} ({} x {} texels, {} levels, {} x {} tiles) in {:.1f} s\n", a->out,
               1 << a->log2, 1 << a->log2, a->log2 + 1, a->tile, a->tile,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    exit_code.value = 0;
  });
}

}  // namespace tmu::texsim
