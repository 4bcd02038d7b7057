#include "texram/mipmap_ideal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tmu::texram {

std::vector<LevelD> ideal_pyramid(const Level8& level0) {
  if (level0.width == 0 || level0.height == 0 ||
      level0.texels.size() != size_t{level0.width} * level0.height) {
    throw std::invalid_argument("ideal_pyramid: empty level 0 or texel count off");
  }
  // Summed-area table: each box sum in four reads, whatever its size.
  const uint32_t w = level0.width, h = level0.height;
  std::vector<double> area(size_t{w + 1} * (h + 1), 0.0);
  auto sat = [&](uint32_t x, uint32_t y) -> double& { return area[size_t{y} * (w + 1) + x]; };
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      sat(x + 1, y + 1) = level0.at(x, y) + sat(x, y + 1) + sat(x + 1, y) - sat(x, y);
    }
  }
  std::vector<LevelD> out;
  for (uint32_t side = 1;; side *= 2) {
    const uint32_t bw = std::min(side, w), bh = std::min(side, h);
    LevelD level{w / bw, h / bh, {}};
    level.texels.resize(size_t{level.width} * level.height);
    for (uint32_t y = 0; y < level.height; ++y) {
      for (uint32_t x = 0; x < level.width; ++x) {
        const uint32_t x0 = x * bw, y0 = y * bh, x1 = x0 + bw, y1 = y0 + bh;
        const double sum = sat(x1, y1) - sat(x0, y1) - sat(x1, y0) + sat(x0, y0);
        level.texels[size_t{y} * level.width + x] = sum / (static_cast<double>(bw) * bh);
      }
    }
    out.push_back(std::move(level));
    if (bw == w && bh == h) return out;
  }
}

std::vector<LevelError> pyramid_error(const Pyramid8& pyramid, const std::vector<LevelD>& ideal) {
  if (pyramid.size() != ideal.size()) {
    throw std::invalid_argument("pyramid_error: the pyramids have different level counts");
  }
  std::vector<LevelError> out;
  for (size_t l = 1; l < pyramid.size(); ++l) {
    const Level8& got = pyramid[l];
    const LevelD& want = ideal[l];
    if (got.width != want.width || got.height != want.height) {
      throw std::invalid_argument("pyramid_error: level sizes differ");
    }
    LevelError e;
    for (size_t i = 0; i < got.texels.size(); ++i) {
      const double d = got.texels[i] - want.texels[i];
      e.mean += d;
      e.max_abs = std::max(e.max_abs, std::abs(d));
    }
    e.mean /= static_cast<double>(got.texels.size());
    out.push_back(e);
  }
  return out;
}

}  // namespace tmu::texram
