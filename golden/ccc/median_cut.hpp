// Global colour quantization for the CCC CLUT (000 §3: "the 24-bit colors can be globally
// quantized to 8 bits, using a standard quantizer such as the Heckbert quantizer").
//
// Heckbert median cut builds the initial palette; a fixed number of Lloyd (k-means)
// iterations then moves each entry to the weighted mean of the colours it serves, which
// median cut alone does not do ("median cut or better").
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ccc/ccc_texture.hpp"
#include "ccc/symmetric_eigen.hpp"
#include "common/image.hpp"

namespace tmu::ccc {

// A colour as a point of RGB space.
inline Vec3 to_vec(Rgb8 c) {
  return {static_cast<double>(c.r), static_cast<double>(c.g), static_cast<double>(c.b)};
}

struct WeightedColour {
  Vec3 rgb{};           // R, G, B in 0..255 (values outside are clamped)
  uint64_t weight = 0;  // e.g. texel count; colours of weight 0 are ignored
};

struct Palette {
  // Entries [0, used) are the palette, sorted by packed RGB so the output does not depend
  // on the order boxes were split in. Entries [used, 256) are black and are never returned
  // by nearest_index(); they exist only because the container always stores 256 entries.
  Clut clut{};
  uint32_t used = 0;  // 1..256
};

inline constexpr int kLloydIterations = 8;

// Quantizes to at most `max_colours` (1..256) entries. If the colours round (to nearest
// 8-bit) to at most `max_colours` distinct values, those values are the palette exactly.
// Throws std::invalid_argument if no colour has a non-zero weight.
Palette median_cut(std::span<const WeightedColour> colours, int max_colours = 256);

// Index of the used palette entry nearest to `rgb` (squared RGB distance, full search,
// ties to the lowest index). Reference implementation of PaletteSearch::nearest.
uint8_t nearest_index(const Palette& palette, const Vec3& rgb);

// Exact nearest-entry search, accelerated: entries are sorted along their widest channel
// and the search walks outward from the query, stopping once that channel alone is farther
// than the best match. Returns exactly what nearest_index() returns.
class PaletteSearch {
 public:
  explicit PaletteSearch(const Palette& palette);
  uint8_t nearest(const Vec3& rgb) const;
  // The min(k, used) entries nearest to `rgb`, nearest first, ties to the lower index: the
  // first is nearest(rgb).
  std::vector<uint8_t> nearest(const Vec3& rgb, size_t k) const;

 private:
  struct Entry {
    Vec3 rgb;
    uint8_t index;
  };
  // Calls consider(entry) for the entries outward from `rgb` along the axis until the
  // squared axis gap exceeds bound().
  template <typename Consider, typename Bound>
  void walk(const Vec3& rgb, Consider&& consider, Bound&& bound) const;
  int axis_ = 0;
  std::vector<Entry> sorted_;  // by rgb[axis_], then index
};

// Rounds a colour channel to the nearest 8-bit value (halves up), clamped to 0..255.
uint8_t round_channel(double v);
Rgb8 round_colour(const Vec3& rgb);

}  // namespace tmu::ccc
