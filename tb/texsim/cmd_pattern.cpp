// `texsim pattern`: the built-in generated images (the bundled demo image is made by it).
#include <fmt/format.h>

#include <memory>

#include "common/image.hpp"
#include "common/test_patterns.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {

void add_pattern_command(CLI::App& app, ExitCode&) {
  auto* cmd = app.add_subcommand("pattern",
                                 "Write a built-in generated image: gradient, checker, noise, "
                                 "smooth, default");
  struct Args {
    std::string name, out;
    int width = 256, height = 256, cell = 8;
    uint32_t seed = 1;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("name", a->name, "Pattern")
      ->required()
      ->check(CLI::IsMember({"gradient", "checker", "noise", "smooth", "default"}));
  cmd->add_option("output", a->out, "Output image (written atomically)")->required();
  cmd->add_option("--width", a->width, "Width in pixels")
      ->check(CLI::Range(1, 16384))
      ->capture_default_str();
  cmd->add_option("--height", a->height, "Height in pixels")
      ->check(CLI::Range(1, 16384))
      ->capture_default_str();
  cmd->add_option("--cell", a->cell, "checker: cell size in pixels")
      ->check(CLI::Range(1, 16384))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "noise, smooth: seed")->capture_default_str();
  cmd->callback([a] {
    ImageRgb8 img;
    if (a->name == "gradient") img = patterns::gradient(a->width, a->height);
    if (a->name == "checker")
      img = patterns::checker(a->width, a->height, a->cell, {0, 0, 0}, {255, 255, 255});
    if (a->name == "noise") img = patterns::noise(a->width, a->height, a->seed);
    if (a->name == "smooth") img = patterns::smooth_field(a->width, a->height, a->seed);
    if (a->name == "default") img = patterns::default_image(a->width, a->height);
    write_image(a->out, img);
    fmt::print("wrote {} ({}x{})\n", a->out, img.width, img.height);
  });
}

}  // namespace tmu::texsim
