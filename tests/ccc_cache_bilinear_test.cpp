// The golden low-cost CCC unit (golden/ccc/ccc_cache_bilinear.hpp): footprint and clamping,
// the footprint's distinct blocks, the lookahead candidates, the claim that the lookahead
// never evicts a block of the current footprint, the statistics on a hand-checked sequence,
// and the error against the ideal bilinear sample.
#include "ccc/ccc_cache_bilinear.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "ccc/ccc_decoder.hpp"
#include "formats/formats.hpp"

namespace tmu::ccc {
namespace {

constexpr int32_t kOne = 256;  // one texel in raw SQ16.8
constexpr int32_t kCoordMin = -(int32_t{1} << 23);
constexpr int32_t kCoordMax = (int32_t{1} << 23) - 1;

static_assert(formats::kTexCoord.frac_bits == 8 && formats::kTexCoord.width() == 24);

int32_t raw(double texels) { return static_cast<int32_t>(std::lround(texels * kOne)); }

// A texture with random CLUT and block words, drawn from the seed.
Texture random_texture(uint32_t width, uint32_t height, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Texture tex;
  tex.width = width;
  tex.height = height;
  for (Rgb8& c : tex.clut) c = unpack_rgb(static_cast<uint32_t>(rng()));
  tex.blocks.resize(size_t{tex.blocks_wide()} * tex.blocks_high());
  for (uint32_t& w : tex.blocks) w = static_cast<uint32_t>(rng());
  return tex;
}

// A unit over `tex` with its CLUT loaded; `fetches` counts the memory reads.
CacheBilinearUnit make_unit(const Texture& tex, bool lookahead, uint64_t* fetches = nullptr) {
  CacheBilinearUnit unit(tex.width, tex.height, lookahead, [&tex, fetches](uint32_t address) {
    if (fetches) ++*fetches;
    return tex.blocks.at(address);
  });
  for (size_t i = 0; i < tex.clut.size(); ++i)
    unit.write_clut(static_cast<uint8_t>(i), pack_rgb(tex.clut[i]));
  return unit;
}

std::vector<BlockXY> blocks_of(const BlockList& list) {
  return {list.at.begin(), list.at.begin() + list.count};
}

// --- footprint ----------------------------------------------------------------------------

TEST(CccCacheBilinearTest, FootprintInsideTheTexture) {
  // u = 3.75: u - 0.5 = 3.25 -> x0 = 3, x1 = 4, fx = 0.25.
  Footprint fp = footprint(raw(3.75), raw(5.5), 16, 16);
  EXPECT_EQ(fp.x0, 3u);
  EXPECT_EQ(fp.x1, 4u);
  EXPECT_EQ(fp.fx, 0x40u);
  // A texel centre: weight 0 on the second texel.
  EXPECT_EQ(fp.y0, 5u);
  EXPECT_EQ(fp.y1, 6u);
  EXPECT_EQ(fp.fy, 0u);
  // The smallest and largest weights.
  fp = footprint(raw(2.5) + 1, raw(2.5) + 255, 16, 16);
  EXPECT_EQ(fp.fx, 1u);
  EXPECT_EQ(fp.fy, 255u);
  EXPECT_EQ(fp.y0, 2u);
  EXPECT_EQ(fp.y1, 3u);
}

TEST(CccCacheBilinearTest, FootprintClampsToTheEdges) {
  // Left / top edge: u - 0.5 = -0.25 -> x0 = -1 -> 0, x1 = 0.
  Footprint fp = footprint(raw(0.25), raw(0.0), 10, 7);
  EXPECT_EQ(fp.x0, 0u);
  EXPECT_EQ(fp.x1, 0u);
  EXPECT_EQ(fp.fx, 0xC0u);
  EXPECT_EQ(fp.y0, 0u);
  EXPECT_EQ(fp.y1, 0u);
  EXPECT_EQ(fp.fy, 0x80u);
  // Right / bottom edge: u - 0.5 = w - 0.75 -> x0 = w - 1, x1 = w -> w - 1.
  fp = footprint(raw(10 - 0.25), raw(7.0), 10, 7);
  EXPECT_EQ(fp.x0, 9u);
  EXPECT_EQ(fp.x1, 9u);
  EXPECT_EQ(fp.y0, 6u);
  EXPECT_EQ(fp.y1, 6u);
  // The last interior footprint: x0 = w - 2, x1 = w - 1.
  fp = footprint(raw(9.0), raw(6.0), 10, 7);
  EXPECT_EQ(fp.x0, 8u);
  EXPECT_EQ(fp.x1, 9u);
  EXPECT_EQ(fp.y0, 5u);
  EXPECT_EQ(fp.y1, 6u);
}

TEST(CccCacheBilinearTest, FootprintOfNegativeAndHugeCoordinates) {
  // Negative: floor, not truncation; everything clamps to texel 0.
  Footprint fp = footprint(raw(-5.3), -1, 10, 7);
  EXPECT_EQ(fp.x0, 0u);
  EXPECT_EQ(fp.x1, 0u);
  EXPECT_EQ(fp.y0, 0u);
  EXPECT_EQ(fp.y1, 0u);
  EXPECT_EQ(fp.fy, 0x7Fu);  // -1/256 - 0.5 = -1 + 127/256
  // The ends of SQ16.8.
  fp = footprint(kCoordMin, kCoordMax, 10, 7);
  EXPECT_EQ(fp.x0, 0u);
  EXPECT_EQ(fp.x1, 0u);
  EXPECT_EQ(fp.fx, 0x80u);
  EXPECT_EQ(fp.y0, 6u);
  EXPECT_EQ(fp.y1, 6u);
  EXPECT_EQ(fp.fy, 0x7Fu);
  // The largest texture.
  fp = footprint(kCoordMax, kCoordMin, 4096, 4096);
  EXPECT_EQ(fp.x0, 4095u);
  EXPECT_EQ(fp.x1, 4095u);
  EXPECT_EQ(fp.y0, 0u);
  EXPECT_EQ(fp.y1, 0u);
  // A one-texel texture: every point reads texel 0.
  for (int32_t u : {kCoordMin, -1, 0, 128, 200, kCoordMax}) {
    fp = footprint(u, u, 1, 1);
    EXPECT_EQ(fp.x0 | fp.x1 | fp.y0 | fp.y1, 0u) << u;
  }
}

// --- footprint blocks ---------------------------------------------------------------------

TEST(CccCacheBilinearTest, FootprintBlocksAreDistinctInLookupOrder) {
  // One block: texels 1..2 in both axes.
  EXPECT_EQ(blocks_of(footprint_blocks(footprint(raw(2.0), raw(2.0), 16, 16))),
            (std::vector<BlockXY>{{0, 0}}));
  // Two blocks across: x0 = 3, x1 = 4.
  EXPECT_EQ(blocks_of(footprint_blocks(footprint(raw(4.0), raw(2.0), 16, 16))),
            (std::vector<BlockXY>{{0, 0}, {1, 0}}));
  // Two blocks down: (x0,y0) then (x0,y1).
  EXPECT_EQ(blocks_of(footprint_blocks(footprint(raw(2.0), raw(8.0), 16, 16))),
            (std::vector<BlockXY>{{0, 1}, {0, 2}}));
  // Four blocks: (x0,y0), (x1,y0), (x0,y1), (x1,y1).
  EXPECT_EQ(blocks_of(footprint_blocks(footprint(raw(12.0), raw(4.0), 16, 16))),
            (std::vector<BlockXY>{{2, 0}, {3, 0}, {2, 1}, {3, 1}}));
  // Clamped at a corner: four texel positions, one block.
  EXPECT_EQ(blocks_of(footprint_blocks(footprint(raw(16.0), raw(16.0), 16, 16))),
            (std::vector<BlockXY>{{3, 3}}));
  // Each block of a footprint sits in its own entry.
  std::mt19937_64 rng(17);
  for (int i = 0; i < 10000; ++i) {
    const auto w = static_cast<uint32_t>(1 + rng() % 40), h = static_cast<uint32_t>(1 + rng() % 40);
    const BlockList list =
        footprint_blocks(footprint(static_cast<int32_t>(rng() % (48 * kOne)) - 4 * kOne,
                                   static_cast<int32_t>(rng() % (48 * kOne)) - 4 * kOne, w, h));
    unsigned slots = 0;
    for (const BlockXY& b : blocks_of(list)) slots |= 1u << cache_slot(b);
    EXPECT_EQ(static_cast<uint32_t>(std::popcount(slots)), list.count);
  }
}

// --- lookahead candidates -----------------------------------------------------------------

TEST(CccCacheBilinearTest, LookaheadCandidatesAtTheTextureEdges) {
  // Interior, far quadrant (t & 2 set in both axes): right, down, diagonal.
  EXPECT_EQ(blocks_of(lookahead_blocks(raw(6.5), raw(7.5), 32, 32)),
            (std::vector<BlockXY>{{2, 1}, {1, 2}, {2, 2}}));
  // Interior, near quadrant: left, up, diagonal.
  EXPECT_EQ(blocks_of(lookahead_blocks(raw(5.5), raw(4.5), 32, 32)),
            (std::vector<BlockXY>{{0, 1}, {1, 0}, {0, 0}}));
  // Top-left block, near quadrant: both neighbours are outside.
  EXPECT_TRUE(blocks_of(lookahead_blocks(raw(1.5), raw(0.5), 32, 32)).empty());
  // Top-left block, far in u only: the right neighbour alone.
  EXPECT_EQ(blocks_of(lookahead_blocks(raw(3.5), raw(1.5), 32, 32)),
            (std::vector<BlockXY>{{1, 0}}));
  // Last block column of a width that is not a multiple of 4 (w = 7: blocks 0, 1): the far
  // half of block 1 has no right neighbour; its near half has the left one.
  EXPECT_EQ(blocks_of(lookahead_blocks(raw(6.5), raw(1.0), 7, 3)), (std::vector<BlockXY>{}));
  EXPECT_EQ(blocks_of(lookahead_blocks(raw(5.9), raw(1.0), 7, 3)), (std::vector<BlockXY>{{0, 0}}));
  // Beyond the texture: t clamps to the last texel (here 5: the near half of block 1).
  EXPECT_EQ(blocks_of(lookahead_blocks(raw(300.0), raw(-300.0), 6, 3)),
            (std::vector<BlockXY>{{0, 0}}));
  // Negative coordinates clamp to texel 0: nothing to the left or above.
  EXPECT_TRUE(blocks_of(lookahead_blocks(kCoordMin, kCoordMin, 64, 64)).empty());
  // Far outside at the other end of a big texture.
  EXPECT_EQ(blocks_of(lookahead_blocks(kCoordMax, kCoordMax, 4096, 4096)),
            (std::vector<BlockXY>{}));  // t = 4095: far half of the last block
  EXPECT_EQ(
      blocks_of(lookahead_blocks(kCoordMax, kCoordMax, 4094, 4094)),
      (std::vector<BlockXY>{{1022, 1023}, {1023, 1022}, {1022, 1022}}));  // t = 4093: near half
  // One-texel and one-block textures have no neighbours.
  EXPECT_TRUE(blocks_of(lookahead_blocks(raw(0.5), raw(0.5), 1, 1)).empty());
  EXPECT_TRUE(blocks_of(lookahead_blocks(raw(3.5), raw(3.5), 4, 4)).empty());
}

// The claim of the header: the three neighbours of the point's quadrant are the blocks next
// to its own block on the footprint's side, so a lookahead block never shares an entry with
// a footprint block other than itself, and after a sample every footprint block is still
// resident. Property test over many random points, sizes and histories.
TEST(CccCacheBilinearTest, LookaheadNeverEvictsTheCurrentFootprint) {
  const uint64_t seed = 20261122;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  for (int t = 0; t < 40; ++t) {
    const auto w = static_cast<uint32_t>(1 + rng() % 70), h = static_cast<uint32_t>(1 + rng() % 70);
    const Texture tex = random_texture(w, h, rng());
    CacheBilinearUnit unit = make_unit(tex, true);
    for (int i = 0; i < 5000; ++i) {
      const int32_t u = static_cast<int32_t>(rng() % ((w + 8) * kOne)) - 4 * kOne;
      const int32_t v = static_cast<int32_t>(rng() % ((h + 8) * kOne)) - 4 * kOne;
      const BlockList need = footprint_blocks(footprint(u, v, w, h));
      const BlockList ahead = lookahead_blocks(u, v, w, h);
      for (const BlockXY& a : blocks_of(ahead)) {
        for (const BlockXY& f : blocks_of(need)) {
          if (cache_slot(a) == cache_slot(f)) {
            ASSERT_EQ(a, f) << "w " << w << " h " << h << " u " << u << " v " << v;
          }
        }
      }
      unit.sample(u, v);
      for (const BlockXY& f : blocks_of(need)) {
        const CacheEntry& e = unit.entries()[cache_slot(f)];
        ASSERT_TRUE(e.valid && e.tag == block_address(f, w))
            << "footprint block evicted: w " << w << " h " << h << " u " << u << " v " << v;
      }
    }
  }
}

// --- statistics ---------------------------------------------------------------------------

TEST(CccCacheBilinearTest, CountersOnAHandCheckedSequence) {
  const Texture tex = random_texture(8, 8, 3);  // 2 x 2 blocks
  for (bool lookahead : {true, false}) {
    SCOPED_TRACE(lookahead ? "lookahead on" : "lookahead off");
    uint64_t fetches = 0;
    CacheBilinearUnit unit = make_unit(tex, lookahead, &fetches);
    auto expect = [&](uint64_t hits, uint64_t misses, uint64_t prefetches, int line) {
      EXPECT_EQ(unit.stats(), (CacheStats{hits, misses, prefetches})) << "after line " << line;
      EXPECT_EQ(fetches, misses + prefetches) << "after line " << line;
    };
    // Footprint x 3..4, y 3..4: four blocks, all missing. The texel (3, 3) is in the far
    // quadrant of block (0, 0): its neighbours are the footprint's own blocks.
    unit.sample(raw(3.75), raw(3.75));
    expect(0, 4, 0, __LINE__);
    unit.sample(raw(3.75), raw(3.75));
    expect(4, 4, 0, __LINE__);
    // A CLUT write empties the cache; x 0..1, y 0..0: block (0, 0) only; texel (1, 1) is in
    // the near quadrant of block (0, 0): no neighbour inside.
    unit.write_clut(0, 0x123456);
    unit.sample(raw(1.0), raw(1.0));
    expect(4, 5, 0, __LINE__);
    // x 2..3: block (0, 0) again; texel (2, 1): far in u -> prefetch (1, 0).
    unit.sample(raw(2.5), raw(1.0));
    expect(5, 5, lookahead ? 1 : 0, __LINE__);
    // x 4..5: block (1, 0), prefetched or not; texel (5, 1): near in u -> (0, 0), present.
    unit.sample(raw(5.0), raw(1.0));
    expect(lookahead ? 6 : 5, lookahead ? 5 : 6, lookahead ? 1 : 0, __LINE__);
    // x 6..7, y 6..7: block (1, 1); texel (7, 7): far quadrant of the last block, nothing.
    unit.sample(raw(7.5), raw(7.5));
    expect(lookahead ? 6 : 5, lookahead ? 6 : 7, lookahead ? 1 : 0, __LINE__);
    // Footprint x 3..4, y 3..4: all four blocks. Since the CLUT write the cache has filled
    // (0,0), (1,0) and (1,1); (0,1) is the one miss. Texel (4, 4) is in the near quadrant of
    // (1,1): left (0,1), up (1,0), diagonal (0,0), all present by then.
    unit.sample(raw(4.0), raw(4.0));
    expect(lookahead ? 9 : 8, lookahead ? 7 : 8, lookahead ? 1 : 0, __LINE__);
  }
}

TEST(CccCacheBilinearTest, BlendOfKnownTexels) {
  // One block, colour a = black, colour b = white; decision bits: texel (1, 0) and (1, 1).
  Texture tex;
  tex.width = tex.height = 4;
  tex.clut[1] = {0, 0, 0};
  tex.clut[2] = {255, 255, 255};
  tex.blocks = {Block{1, 2, 0x0022}.word()};
  CacheBilinearUnit unit = make_unit(tex, true);
  // Texel centres return the texel.
  EXPECT_EQ(unit.sample(raw(0.5), raw(0.5)), 0x000000u);
  EXPECT_EQ(unit.sample(raw(1.5), raw(0.5)), 0xFFFFFFu);
  // Half way between (0, y) and (1, y): 127.5 rounds half up to 128.
  EXPECT_EQ(unit.sample(raw(1.0), raw(0.5)), 0x808080u);
  // fx = 0.25 between black and white over two rows both 0/255: 63.75 -> 64.
  EXPECT_EQ(unit.sample(raw(0.75), raw(1.0)), 0x404040u);
  // The blend rule itself.
  EXPECT_EQ(bilerp_rgb(10, 20, 30, 40, 0x80, 0x40), 20u);
  EXPECT_EQ(bilerp_rgb(0x0A0B0C, 0x141516, 0x1E1F20, 0x28292A, 0, 0), 0x0A0B0Cu);
  EXPECT_EQ(bilerp_rgb(0, 0xFFFFFF, 0, 0xFFFFFF, 255, 77), 0xFEFEFEu);  // 255 * 255/256 = 254.004
}

// --- against the ideal --------------------------------------------------------------------

// On the SQ16.8 grid the weights are exact, so the golden sample differs from the ideal one
// only by its single half-up rounding: at most 0.5 per channel.
TEST(CccCacheBilinearTest, WithinHalfAnLsbOfTheIdealOnTheGrid) {
  const uint64_t seed = 77;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  double max_err = 0.0, sum_err = 0.0;
  uint64_t n = 0;
  for (int t = 0; t < 20; ++t) {
    const auto w = static_cast<uint32_t>(1 + rng() % 100),
               h = static_cast<uint32_t>(1 + rng() % 100);
    const Texture tex = random_texture(w, h, rng());
    CacheBilinearUnit unit = make_unit(tex, true);
    for (int i = 0; i < 20000; ++i) {
      const int32_t u = static_cast<int32_t>(rng() % ((w + 6) * kOne)) - 3 * kOne;
      const int32_t v = static_cast<int32_t>(rng() % ((h + 6) * kOne)) - 3 * kOne;
      const Rgb8 got = unpack_rgb(unit.sample(u, v));
      const std::array<double, 3> ideal = ideal_bilinear(tex, u / 256.0, v / 256.0);
      const double ch[3] = {static_cast<double>(got.r), static_cast<double>(got.g),
                            static_cast<double>(got.b)};
      for (int c = 0; c < 3; ++c) {
        const double err = std::abs(ch[c] - ideal[static_cast<size_t>(c)]);
        max_err = std::max(max_err, err);
        sum_err += err;
        ++n;
        ASSERT_LE(err, 0.5) << "w " << w << " h " << h << " u " << u << " v " << v << " channel "
                            << c;
      }
    }
  }
  std::cout << "golden vs ideal over " << n << " channel samples: max |error| " << max_err
            << ", mean " << sum_err / static_cast<double>(n) << "\n";
  EXPECT_EQ(max_err, 0.5);  // the bound is reached: ties exist and round up
}

}  // namespace
}  // namespace tmu::ccc
