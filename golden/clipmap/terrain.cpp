#include "clipmap/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
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

// The terrain row by row: heights from the noise, a row's colours from its own heights and its
// neighbours' (the shading's slope). Rows are asked for in order; the three rows of heights a
// row's colours need are all that is kept, so a 32k terrain is made in a few hundred KB.
class TerrainRows {
 public:
  TerrainRows(int log2_side, uint32_t seed)
      : side_(1 << log2_side),
        one_(perlin::sum_one(config_)),
        w_(int64_t{seed} * 4096 * 7 + 1234) {}

  int side() const { return side_; }

  void colours(int y, Rgb8* out) {
    const std::vector<double>& above = heights(std::max(y - 1, 0));
    const std::vector<double>& here = heights(y);
    const std::vector<double>& below = heights(std::min(y + 1, side_ - 1));
    for (int x = 0; x < side_; ++x) {
      const auto at = [&](const std::vector<double>& row, int i) {
        return row[static_cast<size_t>(std::clamp(i, 0, side_ - 1))];
      };
      // Shading: the slope towards the light (north-west) brightens, away from it darkens.
      const double slope = (at(above, x - 1) - at(below, x + 1)) * side_ / 64.0;
      const double light = std::clamp(1.0 + 2.0 * slope, 0.55, 1.35);
      const double h = at(here, x);
      const double water = h < 0.45 ? 1.0 : light;
      const Rgb8 c = ramp(h);
      const auto lit = [water](uint8_t v) {
        return static_cast<uint8_t>(std::clamp(std::lround(v * water), 0L, 255L));
      };
      out[x] = {lit(c.r), lit(c.g), lit(c.b)};
    }
    while (!rows_.empty() && rows_.begin()->first < y - 1) rows_.erase(rows_.begin());
  }

 private:
  const std::vector<double>& heights(int y) {
    auto [it, added] = rows_.try_emplace(y);
    if (!added) return it->second;
    std::vector<double>& row = it->second;
    row.resize(static_cast<size_t>(side_));
    // Lattice cells of the noise (4096 raw SolidCoord units each) across the picture:
    // continents of an eighth of it, and hills of a sixty-fourth.
    const auto sums = [&](int x, double cells, int64_t w) {
      const double raw_per_texel = 4096.0 * cells / side_;
      return perlin::fractal_sums(config_, static_cast<int64_t>(x * raw_per_texel),
                                  static_cast<int64_t>(y * raw_per_texel), w);
    };
    for (int x = 0; x < side_; ++x) {
      const double continents = sums(x, 8, w_).fractal_sum / one_;
      const double hills = sums(x, 64, w_ + 4096 * 3).turbulence / one_;
      row[static_cast<size_t>(x)] = 0.5 + 0.45 * continents + 0.18 * hills;
    }
    return row;
  }

  const perlin::NoiseConfig config_;
  const int side_;
  const double one_;
  const int64_t w_;
  std::map<int, std::vector<double>> rows_;  // heights by row: the last three asked for
};

}  // namespace

ImageRgb8 terrain(int log2_side, uint32_t seed) {
  TerrainRows rows(log2_side, seed);
  ImageRgb8 out(rows.side(), rows.side());
  for (int y = 0; y < rows.side(); ++y) rows.colours(y, &out.at(0, y));
  return out;
}

void write_terrain_mipmap(const std::string& path, int log2_side, uint32_t seed, int tile,
                          bool keep_picture) {
  // The picture streamed in bands of rows to an uncompressed TIFF (a 32k terrain is 3 GB).
  const std::string picture = std::filesystem::path(path).replace_extension(".tif").string();
  TerrainRows rows(log2_side, seed);
  write_image_rows(picture, rows.side(), rows.side(), 64, [&](int y, int n, Rgb8* band) {
    for (int i = 0; i < n; ++i) rows.colours(y + i, band + static_cast<size_t>(i) * rows.side());
  });
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
