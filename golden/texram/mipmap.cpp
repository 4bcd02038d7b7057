#include "texram/mipmap.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "formats/formats.hpp"

namespace tmu::texram {

Pyramid8 build_pyramid(const Level8& level0) {
  const auto max_side = uint32_t{1} << formats::kMaxMipLog2;
  if (!std::has_single_bit(level0.width) || !std::has_single_bit(level0.height) ||
      level0.width > max_side || level0.height > max_side) {
    throw std::invalid_argument("build_pyramid: sides must be powers of two up to 1024");
  }
  if (level0.texels.size() != size_t{level0.width} * level0.height) {
    throw std::invalid_argument("build_pyramid: texel count does not match the size");
  }
  Pyramid8 levels{level0};
  while (levels.back().width > 1 || levels.back().height > 1) {
    const Level8& src = levels.back();
    Level8 dst(std::max(src.width / 2, 1u), std::max(src.height / 2, 1u));
    for (uint32_t y = 0; y < dst.height; ++y) {
      for (uint32_t x = 0; x < dst.width; ++x) {
        // A one-texel-wide (-high) source repeats its column (row).
        const uint32_t x0 = std::min(2 * x, src.width - 1), x1 = std::min(2 * x + 1, src.width - 1);
        const uint32_t y0 = std::min(2 * y, src.height - 1),
                       y1 = std::min(2 * y + 1, src.height - 1);
        dst.at(x, y) = box4(src.at(x0, y0), src.at(x1, y0), src.at(x0, y1), src.at(x1, y1));
      }
    }
    levels.push_back(std::move(dst));
  }
  return levels;
}

}  // namespace tmu::texram
