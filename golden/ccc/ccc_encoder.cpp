#include "ccc/ccc_encoder.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "ccc/ccc_decoder.hpp"
#include "ccc/median_cut.hpp"

namespace tmu::ccc {
namespace {

using IVec3 = std::array<int64_t, 3>;

IVec3 channels(Rgb8 c) { return {c.r, c.g, c.b}; }

// Projections closer to the threshold than this fraction of the data's spread count as on
// the plane. It is far above double rounding (~1e-16 relative) and far below the smallest
// real gap between projections of distinct 8-bit colours on a unit axis that is not almost
// perpendicular to their difference.
constexpr double kPlaneTolerance = 1e-9;

int64_t distance2(Rgb8 x, Rgb8 y) {
  const int64_t dr = int64_t{x.r} - y.r;
  const int64_t dg = int64_t{x.g} - y.g;
  const int64_t db = int64_t{x.b} - y.b;
  return dr * dr + dg * dg + db * db;
}

void check_size(const ImageRgb8& image) {
  if (image.width < 1 || image.height < 1 ||
      image.pixels.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height)) {
    throw std::invalid_argument("ccc::encode: the image must be at least 1x1");
  }
}

uint32_t blocks_of(int texels) { return (static_cast<uint32_t>(texels) + 3) / 4; }

// Calls f(bx, by, texels, clusters) for every block in row-major order.
template <typename F>
void for_each_block(const ImageRgb8& image, F&& f) {
  for (uint32_t by = 0; by < blocks_of(image.height); ++by) {
    for (uint32_t bx = 0; bx < blocks_of(image.width); ++bx) {
      const std::array<Rgb8, 16> texels = block_texels(image, bx, by);
      f(bx, by, texels, cluster_block(texels));
    }
  }
}

// The block word of a clustered block: its two colours as CLUT indices, and every texel's
// decision bit re-decided against the two quantized colours.
uint32_t quantized_block(const TwoColourBlock& cluster, const std::array<Rgb8, 16>& texels,
                         const Palette& palette, const PaletteSearch& search) {
  Block block;
  block.a = search.nearest(cluster.a);
  block.b = cluster.bits != 0 ? search.nearest(cluster.b) : block.a;
  // The plane split was made for the exact means; against the quantized colours some
  // texels may now be nearer the other one. Re-deciding never increases the error.
  if (block.a != block.b) {
    const Rgb8 ca = palette.clut[block.a];
    const Rgb8 cb = palette.clut[block.b];
    for (unsigned j = 0; j < 16; ++j) {
      if (distance2(texels[j], cb) < distance2(texels[j], ca)) {
        block.bits = static_cast<uint16_t>(block.bits | (1u << j));
      }
    }
  }
  return block.word();
}

}  // namespace

std::array<Rgb8, 16> block_texels(const ImageRgb8& image, uint32_t bx, uint32_t by) {
  std::array<Rgb8, 16> texels{};
  for (uint32_t y = 0; y < 4; ++y) {
    for (uint32_t x = 0; x < 4; ++x) {
      const int ix = static_cast<int>(std::min<int64_t>(int64_t{4} * bx + x, image.width - 1));
      const int iy = static_cast<int>(std::min<int64_t>(int64_t{4} * by + y, image.height - 1));
      texels[4 * y + x] = image.at(ix, iy);
    }
  }
  return texels;
}

TwoColourBlock cluster_block(const std::array<Rgb8, 16>& texels) {
  // Integer sums make the tensor exact, so it (and everything derived from it) does not
  // depend on the order of the texels.
  IVec3 sum{};
  std::array<IVec3, 3> moment{};  // sum of x x^T
  for (Rgb8 t : texels) {
    const IVec3 x = channels(t);
    for (int i = 0; i < 3; ++i) {
      sum[i] += x[i];
      for (int k = 0; k < 3; ++k) moment[i][k] += x[i] * x[k];
    }
  }
  // Eq. 1 is taken about the block's mean colour, not the origin: about the origin the
  // tensor is dominated by the mean's own "mass" and its axis points toward black rather
  // than along the colours' spread, and the text's "the mean color is in the cutting
  // plane" describes a plane through the mean. With y = x - mean, the scatter 16 * sum(y
  // y^T) = 16 * sum(x x^T) - S S^T, and the tensor is trace(scatter) * I - scatter.
  std::array<IVec3, 3> scatter16{};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) scatter16[i][k] = 16 * moment[i][k] - sum[i] * sum[k];
  }
  const int64_t trace16 = scatter16[0][0] + scatter16[1][1] + scatter16[2][2];
  Mat3 inertia{};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      inertia[i][k] = static_cast<double>((i == k ? trace16 : 0) - scatter16[i][k]);
    }
  }
  // Minimum moment of inertia = the direction along which the colours spread the most.
  const Vec3 axis = symmetric_eigen(inertia).vectors[0];

  // Signed distance of 16 * x_j from the plane through the mean: axis . (16 x_j - S).
  // Multiplying by 16 keeps the offset integral, so equal colours get equal distances.
  std::array<double, 16> distance{};
  double spread = 0.0;
  for (size_t j = 0; j < 16; ++j) {
    const IVec3 x = channels(texels[j]);
    double d = 0.0;
    for (int k = 0; k < 3; ++k) {
      const int64_t offset = 16 * x[k] - sum[k];
      d += axis[k] * static_cast<double>(offset);
      spread = std::max(spread, static_cast<double>(std::llabs(offset)));
    }
    distance[j] = d;
  }
  const double tolerance = kPlaneTolerance * spread;

  TwoColourBlock out;
  IVec3 sum_a{};
  IVec3 sum_b{};
  int count_b = 0;
  for (size_t j = 0; j < 16; ++j) {
    const IVec3 x = channels(texels[j]);
    // Ties (on the plane) go to a, so a one-colour block is all a with no bits set.
    const bool take_b = distance[j] > tolerance;
    IVec3& s = take_b ? sum_b : sum_a;
    for (int k = 0; k < 3; ++k) s[k] += x[k];
    if (take_b) {
      out.bits = static_cast<uint16_t>(out.bits | (1u << j));
      ++count_b;
    }
  }
  // Cluster a is never empty: the smallest distance cannot exceed the mean distance, 0.
  const int count_a = 16 - count_b;
  for (int k = 0; k < 3; ++k) {
    out.a[k] = static_cast<double>(sum_a[k]) / count_a;
    out.b[k] = count_b > 0 ? static_cast<double>(sum_b[k]) / count_b : out.a[k];
  }
  return out;
}

Texture encode(const ImageRgb8& image) { return encode_levels({image}).front(); }

std::vector<Texture> encode_levels(const std::vector<ImageRgb8>& images) {
  struct Pending {
    TwoColourBlock cluster;
    std::array<Rgb8, 16> texels;
  };
  std::vector<std::vector<Pending>> pending(images.size());
  std::vector<WeightedColour> colours;
  for (size_t i = 0; i < images.size(); ++i) {
    check_size(images[i]);
    for_each_block(images[i], [&](uint32_t, uint32_t, const std::array<Rgb8, 16>& texels,
                                  const TwoColourBlock& c) {
      const auto count_b = static_cast<uint64_t>(std::popcount(c.bits));
      // Weights are texel counts, so the CLUT is spent where most texels are.
      colours.push_back({c.a, 16 - count_b});
      if (count_b > 0) colours.push_back({c.b, count_b});
      pending[i].push_back({c, texels});
    });
  }
  if (images.empty()) throw std::invalid_argument("ccc::encode_levels: no image");

  const Palette palette = median_cut(colours);
  const PaletteSearch search(palette);
  std::vector<Texture> out;
  for (size_t i = 0; i < images.size(); ++i) {
    Texture& tex = out.emplace_back();
    tex.width = static_cast<uint32_t>(images[i].width);
    tex.height = static_cast<uint32_t>(images[i].height);
    tex.clut = palette.clut;
    tex.blocks.reserve(pending[i].size());
    for (const Pending& p : pending[i])
      tex.blocks.push_back(quantized_block(p.cluster, p.texels, palette, search));
  }
  return out;
}

Texture encode_with_clut(const ImageRgb8& image, const Clut& clut) {
  check_size(image);
  const Palette palette{clut, static_cast<uint32_t>(clut.size())};
  const PaletteSearch search(palette);
  Texture tex;
  tex.width = static_cast<uint32_t>(image.width);
  tex.height = static_cast<uint32_t>(image.height);
  tex.clut = clut;
  for_each_block(
      image, [&](uint32_t, uint32_t, const std::array<Rgb8, 16>& texels, const TwoColourBlock& c) {
        tex.blocks.push_back(quantized_block(c, texels, palette, search));
      });
  return tex;
}

ImageRgb8 two_colour_ideal(const ImageRgb8& image) {
  check_size(image);
  ImageRgb8 out(image.width, image.height);
  for_each_block(
      image, [&](uint32_t bx, uint32_t by, const std::array<Rgb8, 16>&, const TwoColourBlock& c) {
        const Rgb8 a = round_colour(c.a);
        const Rgb8 b = round_colour(c.b);
        for (uint32_t j = 0; j < 16; ++j) {
          const int64_t x = int64_t{4} * bx + j % 4;
          const int64_t y = int64_t{4} * by + j / 4;
          if (x >= image.width || y >= image.height) continue;  // padding
          out.at(static_cast<int>(x), static_cast<int>(y)) = ((c.bits >> j) & 1u) != 0 ? b : a;
        }
      });
  return out;
}

EncodeReport report_encoding(const ImageRgb8& input, const Texture& encoded) {
  EncodeReport r;
  r.psnr_ideal = psnr(two_colour_ideal(input), input);
  r.psnr_encoded = psnr(decode_image(encoded), input);
  const double texels = static_cast<double>(input.width) * static_cast<double>(input.height);
  r.bits_per_texel = static_cast<double>(serialize(encoded).size()) * 8.0 / texels;
  return r;
}

EncodeReport report_encoding(const ImageRgb8& input) {
  return report_encoding(input, encode(input));
}

}  // namespace tmu::ccc
