// The golden mipmap generator (000 §12, Fig. 14): the rounding rule at its extremes and against
// the exact box means, the pyramid of the degenerate sizes, and the streaming model against
// build_pyramid for every size and carry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>

#include "formats/formats.hpp"
#include "texram/layout.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"
#include "texram/mipmap_ideal.hpp"

namespace tmu::texram {
namespace {

Level8 random_level(uint32_t w, uint32_t h, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Level8 l(w, h);
  for (uint8_t& t : l.texels) t = static_cast<uint8_t>(rng());
  return l;
}

Level8 make_level(uint32_t w, uint32_t h, std::initializer_list<uint8_t> texels) {
  Level8 l(w, h);
  l.texels.assign(texels);
  return l;
}

// ---- the rounding rule -------------------------------------------------------------------

TEST(MipgenTest, BoxTexelRoundsOnceHalfUp) {
  // Four 8-bit values (k = 0): the old box4 rule at its extremes.
  EXPECT_EQ(box_texel(0, 0), 0);
  EXPECT_EQ(box_texel(1020, 0), 255);  // all 255: + 2 stays below 1024
  EXPECT_EQ(box_texel(1019, 0), 255);
  EXPECT_EQ(box_texel(1018, 0), 255);  // a tie, rounded up
  EXPECT_EQ(box_texel(1017, 0), 254);
  EXPECT_EQ(box_texel(510, 0), 128);  // 4 * 127 + 2: a tie, up to 128
  // Every sum 4u + r of values with k fraction bits (scaled by 2^k): r < 2^(k+1) rounds down,
  // the rest up, ties (r = 2^(k+1)) included.
  for (int k : {0, 2, 7, kExactCarry}) {
    const uint32_t one = 4u << k;  // the box sum of a mean of 1
    for (uint32_t u : {0u, 1u, 127u, 254u}) {
      EXPECT_EQ(box_texel(u * one + one / 2 - 1, k), u) << k;
      EXPECT_EQ(box_texel(u * one + one / 2, k), u + 1) << k;
      EXPECT_EQ(box_texel(u * one + one - 1, k), u + 1) << k;
    }
  }
}

TEST(MipgenTest, BoxCarryKeepsOrRoundsTheFraction) {
  EXPECT_EQ(box_carry(1019, 0, 2), 1019u);  // two more bits: exact
  EXPECT_EQ(box_carry(1019, 0, 1), 510u);   // 1019 / 2 = 509.5, a tie: up
  EXPECT_EQ(box_carry(1017, 0, 0), 254u);   // the rounded texel
  EXPECT_EQ(box_carry(1018, 0, 0), 255u);
  EXPECT_EQ(carried_bits(0, kExactCarry), 0);
  EXPECT_EQ(carried_bits(10, kExactCarry), 20);
  EXPECT_EQ(carried_bits(5, 3), 3);
}

// The ideal pyramid on its own: the box means of a 4 x 2 level 0, the last level repeating its
// row (which leaves a mean unchanged).
TEST(MipgenTest, IdealPyramidIsTheBoxMeans) {
  const std::vector<LevelD> p = ideal_pyramid(make_level(4, 2,
                                                         {0, 4, 8, 9,  //
                                                          2, 6, 9, 9}));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1].texels, (std::vector<double>{3.0, 8.75}));
  EXPECT_EQ(p[2].texels, (std::vector<double>{5.875}));
}

// Every level of the default (exact) rule is within 0.5 of the ideal (the exact box mean of
// level 0: one rounding, half up), and carry 0 is the rule of rounding every level from the
// rounded level below; both for shapes of 2^0..2^10 per side, random texels.
TEST(MipgenTest, ExactRuleIsWithinHalfOfTheBoxMeanAndCarryZeroRoundsEveryLevel) {
  for (int lw = 0; lw <= formats::kMaxMipLog2; lw += 2) {
    for (int lh = 0; lh <= formats::kMaxMipLog2; lh += 3) {
      SCOPED_TRACE(::testing::Message() << (1u << lw) << " x " << (1u << lh));
      const Level8 level0 = random_level(1u << lw, 1u << lh, 77 + 16 * lw + lh);
      const std::vector<LevelError> error =
          pyramid_error(build_pyramid(level0), ideal_pyramid(level0));
      for (size_t l = 0; l < error.size(); ++l)
        EXPECT_LE(error[l].max_abs, 0.5) << "level " << l + 1;
      const Pyramid8 rounded = build_pyramid(level0, 0);
      for (size_t l = 1; l < rounded.size(); ++l) {
        const Level8& below = rounded[l - 1];
        for (uint32_t y = 0; y < rounded[l].height; ++y) {
          for (uint32_t x = 0; x < rounded[l].width; ++x) {
            // The box of the four rounded texels below (a one-texel side taken twice).
            const uint32_t x0 = std::min(2 * x, below.width - 1),
                           x1 = std::min(2 * x + 1, below.width - 1);
            const uint32_t y0 = std::min(2 * y, below.height - 1),
                           y1 = std::min(2 * y + 1, below.height - 1);
            const uint32_t box =
                below.at(x0, y0) + below.at(x1, y0) + below.at(x0, y1) + below.at(x1, y1);
            ASSERT_EQ(rounded[l].at(x, y), (box + 2) >> 2) << "level " << l;
          }
        }
      }
    }
  }
}

// ---- build_pyramid ------------------------------------------------------------------------

TEST(MipgenTest, PyramidOfOneTexelIsItself) {
  const Pyramid8 p = build_pyramid(make_level(1, 1, {77}));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].at(0, 0), 77);
}

TEST(MipgenTest, PyramidOfASingleLineRepeatsTheRow) {
  // 4 x 1: a level-1 texel is the mean of its pair, (a + b) / 2 rounded half up; level 2 the
  // mean of all four, 266 / 4 = 66.5 -> 67.
  const Pyramid8 p = build_pyramid(make_level(4, 1, {0, 1, 10, 255}));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], make_level(2, 1, {1, 133}));  // 0.5 -> 1, 132.5 -> 133
  EXPECT_EQ(p[2], make_level(1, 1, {67}));
}

TEST(MipgenTest, PyramidOfASingleColumnRepeatsTheColumn) {
  const Pyramid8 p = build_pyramid(make_level(1, 4, {0, 1, 10, 255}));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], make_level(1, 2, {1, 133}));
  EXPECT_EQ(p[2], make_level(1, 1, {67}));
}

TEST(MipgenTest, PyramidOfANonSquareTexture) {
  // 4 x 2 -> 2 x 1 -> 1 x 1; the last step repeats the row: the mean of all eight.
  const Pyramid8 p = build_pyramid(make_level(4, 2,
                                              {0, 4, 8, 9,  //
                                               2, 6, 9, 9}));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], make_level(2, 1, {3, 9}));  // 12 / 4 = 3, 35 / 4 = 8.75 -> 9
  EXPECT_EQ(p[2], make_level(1, 1, {6}));     // 47 / 8 = 5.875 -> 6
}

TEST(MipgenTest, PyramidRejectsNonPowerOfTwoSides) {
  EXPECT_THROW(build_pyramid(Level8(3, 4)), std::invalid_argument);
  EXPECT_THROW(build_pyramid(Level8(2048, 1)), std::invalid_argument);
  EXPECT_THROW(build_pyramid(Level8(2, 2), kExactCarry + 1), std::invalid_argument);
}

// ---- the streaming model ------------------------------------------------------------------

// One frame of `level0` through the stream: the writes read back through Geometry::cell
// must be build_pyramid, every cell of the layout written exactly once, and every write in
// the documented order.
void expect_stream_is_pyramid(const MipgenConfig& cfg, const Level8& level0,
                              int carry = kExactCarry) {
  SCOPED_TRACE(::testing::Message() << (1u << cfg.log2_w) << " x " << (1u << cfg.log2_h)
                                    << (cfg.interlaced ? " interlaced" : "") << " plane "
                                    << cfg.plane << "/" << cfg.planes << " carry " << carry);
  const std::vector<CellWrite> writes = mipgen_frame(cfg, level0, carry);
  const Geometry g(cfg.log2_w, cfg.log2_h, cfg.planes);
  BankMemory mem(g);
  for (const CellWrite& w : writes) {
    ASSERT_EQ(w.cell, g.cell(w.level, w.x, w.y, cfg.plane));
    mem.write(w);
  }
  EXPECT_EQ(mem.read_pyramid(cfg.plane), build_pyramid(level0, carry));
  EXPECT_EQ(mem.cells_not_written_once(cfg.plane), 0u);
}

TEST(MipgenTest, StreamEqualsPyramidForEveryCarry) {
  for (int carry = 0; carry <= kExactCarry; ++carry) {
    for (bool interlaced : {false, true}) {
      expect_stream_is_pyramid({7, 6, interlaced, 1, 0}, random_level(128, 64, 5), carry);
      expect_stream_is_pyramid({0, 5, interlaced, 1, 0}, random_level(1, 32, 6), carry);
    }
  }
}

TEST(MipgenTest, StreamEqualsPyramidForEverySizeBothModes) {
  // All 121 combinations of 2^0..2^10 per side, random texels, interlaced and not.
  const uint64_t seed = 20261122;
  std::cout << "seed " << seed << "\n";
  for (int lw = 0; lw <= formats::kMaxMipLog2; ++lw) {
    for (int lh = 0; lh <= formats::kMaxMipLog2; ++lh) {
      const Level8 level0 = random_level(1u << lw, 1u << lh, seed + 16 * lw + lh);
      for (bool interlaced : {false, true}) {
        expect_stream_is_pyramid({lw, lh, interlaced, 1, 0}, level0);
      }
      if (HasFailure()) return;
    }
  }
}

TEST(MipgenTest, StreamEqualsPyramidForEveryPlane) {
  const Level8 level0 = random_level(64, 8, 3);
  for (int plane = 0; plane < formats::kPlanes; ++plane) {
    expect_stream_is_pyramid({6, 3, true, 4, plane}, level0);
    expect_stream_is_pyramid({6, 3, false, 4, plane}, level0);
  }
}

TEST(MipgenTest, StreamEqualsPyramidOnConstantAndAlternatingFrames) {
  for (const auto& [lw, lh] : {std::pair{0, 0}, {10, 0}, {0, 10}, {3, 5}, {9, 8}}) {
    const uint32_t w = 1u << lw, h = 1u << lh;
    Level8 zero(w, h), full(w, h), alt(w, h);
    std::fill(full.texels.begin(), full.texels.end(), 255);
    for (uint32_t y = 0; y < h; ++y) {
      for (uint32_t x = 0; x < w; ++x) alt.at(x, y) = ((x + y) & 1) ? 255 : 0;
    }
    for (bool interlaced : {false, true}) {
      for (const Level8* l : {&zero, &full, &alt}) {
        expect_stream_is_pyramid({lw, lh, interlaced, 1, 0}, *l);
      }
    }
  }
}

// The output order: per item, level-0 writes first, then ascending levels, replicas in
// row-major order of their stored coordinates; each frame of a multi-frame run the same.
TEST(MipgenTest, WritesComeInTheDocumentedOrder) {
  for (const auto& [lw, lh, il] :
       {std::tuple{0, 0, false}, {1, 0, true}, {0, 3, true}, {4, 2, false}, {3, 4, true}}) {
    const MipgenConfig cfg{lw, lh, il, 1, 0};
    MipgenStream s(cfg);
    const Level8 level0 = random_level(1u << lw, 1u << lh, 9);
    const std::vector<MipgenInput> items = mipgen_source(level0, il);
    std::vector<CellWrite> first_frame;
    for (int frame = 0; frame < 2; ++frame) {
      std::vector<CellWrite> frame_writes;
      for (const MipgenInput& in : items) {
        EXPECT_EQ(s.frame_start(), &in == &items.front());
        const uint32_t x = s.next_x(), y = s.next_y();
        std::vector<CellWrite> w;
        s.step(in, w);
        ASSERT_FALSE(w.empty());
        EXPECT_EQ(w[0].level, 0);
        EXPECT_EQ(w[0].x, lw == 0 ? 0 : x);
        EXPECT_EQ(w[0].y, lh == 0 ? 0 : y);
        for (size_t i = 1; i < w.size(); ++i) {
          ASSERT_GE(w[i].level, w[i - 1].level);
          if (w[i].level == w[i - 1].level) {  // a replica: after its predecessor, row-major
            EXPECT_EQ(w[i].value, w[i - 1].value);
            EXPECT_LT(std::pair(w[i - 1].y, w[i - 1].x), std::pair(w[i].y, w[i].x));
          } else {
            EXPECT_EQ(w[i].level, w[i - 1].level + 1);
          }
        }
        frame_writes.insert(frame_writes.end(), w.begin(), w.end());
      }
      if (frame == 0) first_frame = frame_writes;
      EXPECT_EQ(frame_writes, first_frame) << "frame " << frame;
    }
  }
}

// Interlaced: level 1 of field 2 is built from the item's `above`, as the chip reads it back.
TEST(MipgenTest, InterlacedLevel1UsesTheLineAbove) {
  const Level8 level0 = make_level(2, 2, {10, 20, 30, 40});
  MipgenStream s({1, 1, true, 1, 0});
  std::vector<CellWrite> w;
  s.step({10, 0}, w);  // field 1: (0, 0), (1, 0)
  s.step({20, 0}, w);
  EXPECT_TRUE(s.needs_above());
  s.step({30, 99}, w);  // field 2, a wrong `above` for (0, 1)
  s.step({40, 20}, w);
  ASSERT_EQ(w.back().level, 1);
  EXPECT_EQ(w.back().value, box_texel(99 + 20 + 30 + 40, 0));
  EXPECT_NE(w.back().value, build_pyramid(level0)[1].at(0, 0));
  EXPECT_TRUE(s.frame_start());
}

// Fig. 14: the line FIFO of each level never holds more than half a line of that level's
// input (one entry for a one-texel-wide level), and does fill to that depth. The interlaced
// level 0 uses no line FIFO (one register), the levels above it do.
TEST(MipgenTest, LineFifoHoldsAtMostHalfALinePerLevel) {
  for (const auto& [lw, lh] : {std::pair{10, 10}, {10, 1}, {0, 10}, {7, 3}, {2, 9}}) {
    for (bool interlaced : {false, true}) {
      SCOPED_TRACE(::testing::Message() << lw << " x " << lh << (interlaced ? " interlaced" : ""));
      MipgenStream s({lw, lh, interlaced, 1, 0});
      const Level8 level0 = random_level(1u << lw, 1u << lh, 5);
      std::vector<CellWrite> w;
      const int stages = s.geometry().levels() - 1;
      for (const MipgenInput& in : mipgen_source(level0, interlaced)) {
        s.step(in, w);
        w.clear();
        for (int l = 0; l < stages; ++l) ASSERT_LE(s.fifo_size(l), s.fifo_depth(l));
      }
      for (int l = 0; l < stages; ++l) {
        const uint32_t half_line = std::max(s.geometry().texel_width(l) / 2, 1u);
        EXPECT_EQ(s.fifo_depth(l), half_line);
        EXPECT_LE(s.fifo_peak(l), half_line) << "level " << l;
        const bool uses_fifo = s.geometry().texel_height(l) >= 2 && !(interlaced && l == 0);
        EXPECT_EQ(s.fifo_peak(l), uses_fifo ? half_line : 0u) << "level " << l;
        EXPECT_EQ(s.fifo_size(l), 0u) << "level " << l << ": a frame leaves its FIFO empty";
      }
      // The depth halves from one level to the next (000 §12), down to one entry.
      for (int l = 1; l < stages; ++l) {
        EXPECT_EQ(s.fifo_depth(l), std::max(s.fifo_depth(l - 1) / 2, 1u));
      }
    }
  }
}

TEST(MipgenTest, RejectsBadConfigurations) {
  EXPECT_THROW(MipgenStream({11, 0, false, 1, 0}), std::invalid_argument);
  EXPECT_THROW(MipgenStream({0, -1, false, 1, 0}), std::invalid_argument);
  EXPECT_THROW(MipgenStream({2, 2, false, 3, 0}), std::invalid_argument);
  EXPECT_THROW(MipgenStream({2, 2, false, 4, 4}), std::invalid_argument);
  EXPECT_THROW(MipgenStream({2, 2, false, 1, 1}), std::invalid_argument);
  EXPECT_THROW(mipgen_frame({2, 2, false, 1, 0}, Level8(4, 2)), std::invalid_argument);
}

TEST(MipgenTest, BankMemoryNamesAnUnwrittenCell) {
  const MipgenConfig cfg{2, 1, false, 1, 0};
  std::vector<CellWrite> writes = mipgen_frame(cfg, random_level(4, 2, 1));
  const Geometry g(2, 1);
  BankMemory mem(g);
  for (size_t i = 0; i + 1 < writes.size(); ++i) mem.write(writes[i]);  // the last one lost
  EXPECT_THROW(mem.read_pyramid(0), std::runtime_error);
  EXPECT_EQ(mem.cells_not_written_once(0), 1u);
  CellWrite bad = writes[0];
  bad.cell.address = g.bank_cells();
  EXPECT_THROW(mem.write(bad), std::out_of_range);
}

}  // namespace
}  // namespace tmu::texram
