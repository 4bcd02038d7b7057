#include "clipmap/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "common/error.hpp"
#include "perlin/noise.hpp"

namespace tmu::clipmap {
namespace {

struct Stop {
  double height;
  Rgb8 colour;
};
// Height 0..1 to colour: deep and shallow water, sand, grass, forest, rock, snow.
constexpr Stop kRamp[] = {{0.00, {20, 40, 110}},   {0.40, {40, 90, 170}},  {0.45, {210, 200, 140}},
                          {0.50, {90, 150, 60}},   {0.62, {40, 100, 40}},  {0.75, {120, 110, 100}},
                          {0.88, {200, 200, 200}}, {1.00, {255, 255, 255}}};

Rgb8 ramp(double h) {
  h = std::clamp(h, 0.0, 1.0);
  for (size_t i = 1; i < std::size(kRamp); ++i) {
    if (h > kRamp[i].height) continue;
    const Stop& a = kRamp[i - 1];
    const Stop& b = kRamp[i];
    const double t = (h - a.height) / (b.height - a.height);
    const auto mix = [t](uint8_t x, uint8_t y) {
      return static_cast<uint8_t>(std::lround(x + (y - x) * t));
    };
    return {mix(a.colour.r, b.colour.r), mix(a.colour.g, b.colour.g), mix(a.colour.b, b.colour.b)};
  }
  return kRamp[std::size(kRamp) - 1].colour;
}

}  // namespace

ImageRgb8 terrain(int log2_side, uint32_t seed) {
  const int side = 1 << log2_side;
  const perlin::NoiseConfig config;
  const double one = perlin::sum_one(config);
  // Lattice cells of the noise (4096 raw SolidCoord units each) across the picture: continents
  // of an eighth of it, and hills of a sixty-fourth.
  const auto sums = [&](int x, int y, double cells, int64_t w) {
    const double raw_per_texel = 4096.0 * cells / side;
    return perlin::fractal_sums(config, static_cast<int64_t>(x * raw_per_texel),
                                static_cast<int64_t>(y * raw_per_texel), w);
  };
  std::vector<double> height(static_cast<size_t>(side) * side);
  const int64_t w = int64_t{seed} * 4096 * 7 + 1234;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const double continents = sums(x, y, 8, w).fractal_sum / one;
      const double hills = sums(x, y, 64, w + 4096 * 3).turbulence / one;
      height[static_cast<size_t>(y) * side + x] = 0.5 + 0.45 * continents + 0.18 * hills;
    }
  }
  ImageRgb8 out(side, side);
  const auto h = [&](int x, int y) {
    return height[static_cast<size_t>(std::clamp(y, 0, side - 1)) * side +
                  std::clamp(x, 0, side - 1)];
  };
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      // Shading: the slope towards the light (north-west) brightens, away from it darkens.
      const double slope = (h(x - 1, y - 1) - h(x + 1, y + 1)) * side / 64.0;
      const double light = std::clamp(1.0 + 2.0 * slope, 0.55, 1.35);
      const double water = h(x, y) < 0.45 ? 1.0 : light;
      const Rgb8 c = ramp(h(x, y));
      const auto lit = [water](uint8_t v) {
        return static_cast<uint8_t>(std::clamp(std::lround(v * water), 0L, 255L));
      };
      out.at(x, y) = {lit(c.r), lit(c.g), lit(c.b)};
    }
  }
  return out;
}

void write_terrain_mipmap(const std::string& path, int log2_side, uint32_t seed, int tile,
                          bool keep_picture) {
  const std::string picture = std::filesystem::path(path).replace_extension(".png").string();
  write_image(picture, terrain(log2_side, seed));
  const std::string tmp = path + ".tmp.tx";
  const std::string command = "maketx --filter box --tile " + std::to_string(tile) + " " +
                              std::to_string(tile) + " -o '" + tmp + "' '" + picture +
                              "' >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  if (!keep_picture) std::filesystem::remove(picture);
  if (status != 0) {
    std::filesystem::remove(tmp);
    throw InputError(path, "", "maketx failed (is openimageio-tools installed?): " + command);
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace tmu::clipmap
