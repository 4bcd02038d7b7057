// `texsim bumpmap`: a height map (grey image) to a bump map of deflection angles (001 §4.2;
// golden/deflect/bump_map.hpp gives the texel format).
#include <fmt/format.h>

#include <memory>

#include "common/image.hpp"
#include "deflect/bump_map.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {

void add_bumpmap_command(CLI::App& app, ExitCode&) {
  auto* cmd = app.add_subcommand(
      "bumpmap",
      "Turn a height map (luminance 0..1) into a bump map: per texel the deflected normal as "
      "angles\n(phi_D, theta_D) on the sphere grid, packed R = phi_D[7:0], G = |theta_D|, "
      "B = sign << 7 | phi_D[A-1:8]\n(docs/deflection.md). Sample it with the nearest filter.");
  struct Args {
    std::string in, out;
    double scale = 4.0;
    int grid = 9;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("heights", a->in, "Height map image (PNG, any size; wraps at its edges)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("output", a->out, "Bump map image (written atomically)")->required();
  cmd->add_option("--scale", a->scale, "Height of luminance 1, in texels")
      ->check(CLI::Range(0.0, 1024.0))
      ->capture_default_str();
  cmd->add_option("--grid", a->grid, "Sphere grid A: 2^A x 2^(A-1) angles (9: 512 x 256)")
      ->check(CLI::Range(6, deflect::kMaxBumpGridBits))
      ->capture_default_str();
  cmd->callback([a] {
    const ImageRgb8 heights = read_image(a->in);
    const ImageRgb8 bump =
        deflect::bump_map_from_heights(heights, a->scale, deflect::SphereGrid{a->grid});
    write_image(a->out, bump);
    fmt::print("wrote {} ({}x{}, grid {}x{})\n", a->out, bump.width, bump.height, 1 << a->grid,
               1 << (a->grid - 1));
  });
}

}  // namespace tmu::texsim
