#include "texram/mipmap.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "formats/formats.hpp"

namespace tmu::texram {

Pyramid8 build_pyramid(const Level8& level0, int carry) {
  const auto max_side = uint32_t{1} << formats::kMaxMipLog2;
  if (!std::has_single_bit(level0.width) || !std::has_single_bit(level0.height) ||
      level0.width > max_side || level0.height > max_side) {
    throw std::invalid_argument("build_pyramid: sides must be powers of two up to 1024");
  }
  if (level0.texels.size() != size_t{level0.width} * level0.height) {
    throw std::invalid_argument("build_pyramid: texel count does not match the size");
  }
  if (carry < 0 || carry > kExactCarry) {
    throw std::invalid_argument("build_pyramid: carry must be 0.." + std::to_string(kExactCarry));
  }
  Pyramid8 levels{level0};
  // The carried values of the level last built, row-major (level 0: its texels).
  std::vector<uint32_t> carried(level0.texels.begin(), level0.texels.end());
  for (int l = 0; levels.back().width > 1 || levels.back().height > 1; ++l) {
    const Level8& src = levels.back();
    const uint32_t sw = src.width, sh = src.height;
    Level8 dst(std::max(sw / 2, 1u), std::max(sh / 2, 1u));
    std::vector<uint32_t> next(dst.texels.size());
    const int k = carried_bits(l, carry), k_next = carried_bits(l + 1, carry);
    for (uint32_t y = 0; y < dst.height; ++y) {
      for (uint32_t x = 0; x < dst.width; ++x) {
        // A one-texel-wide (-high) source repeats its column (row).
        const uint32_t x0 = std::min(2 * x, sw - 1), x1 = std::min(2 * x + 1, sw - 1);
        const uint32_t y0 = std::min(2 * y, sh - 1), y1 = std::min(2 * y + 1, sh - 1);
        const uint32_t sum = carried[y0 * sw + x0] + carried[y0 * sw + x1] + carried[y1 * sw + x0] +
                             carried[y1 * sw + x1];
        dst.at(x, y) = box_texel(sum, k);
        next[size_t{y} * dst.width + x] = box_carry(sum, k, k_next);
      }
    }
    levels.push_back(std::move(dst));
    carried = std::move(next);
  }
  return levels;
}

}  // namespace tmu::texram
