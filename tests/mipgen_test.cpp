// The golden mipmap generator (000 §12, Fig. 14): the box rule at its extremes, the pyramid
// of the degenerate sizes, and the streaming model against build_pyramid for every size.
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <stdexcept>

#include "formats/formats.hpp"
#include "texram/layout.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"

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

// ---- box4 ---------------------------------------------------------------------------------

TEST(MipgenTest, Box4AtTheExtremes) {
  EXPECT_EQ(box4(0, 0, 0, 0), 0);
  EXPECT_EQ(box4(255, 255, 255, 255), 255);  // sum 1020: + 2 stays below 1024
  EXPECT_EQ(box4(255, 255, 255, 254), 255);  // 1019 + 2 = 1021 -> 255
  EXPECT_EQ(box4(255, 255, 254, 254), 255);  // 1018: a tie, rounded up
  EXPECT_EQ(box4(255, 254, 254, 254), 254);  // 1017 -> 254
  EXPECT_EQ(box4(0, 0, 0, 1), 0);            // 1: rounds down
  EXPECT_EQ(box4(255, 0, 255, 0), 128);      // 510 = 4 * 127 + 2: a tie, up to 128
}

TEST(MipgenTest, Box4RoundsTiesUp) {
  // Every sum 4k + 2 is exactly between k and k + 1 and gives k + 1; 4k + 1 gives k and
  // 4k + 3 gives k + 1.
  for (uint32_t k = 0; k < 255; ++k) {
    EXPECT_EQ(round_box_sum(4 * k + 1), k);
    EXPECT_EQ(round_box_sum(4 * k + 2), k + 1);
    EXPECT_EQ(round_box_sum(4 * k + 3), k + 1);
  }
  EXPECT_EQ(box4(1, 1, 0, 0), 1);  // 2/4 = 0.5 -> 1
  EXPECT_EQ(box4(1, 0, 0, 0), 0);  // 0.25 -> 0
}

// ---- build_pyramid ------------------------------------------------------------------------

TEST(MipgenTest, PyramidOfOneTexelIsItself) {
  const Pyramid8 p = build_pyramid(make_level(1, 1, {77}));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].at(0, 0), 77);
}

TEST(MipgenTest, PyramidOfASingleLineRepeatsTheRow) {
  // 4 x 1: level 1 = box4(a, b, a, b) = (2a + 2b + 2) >> 2 = (a + b + 1) >> 1.
  const Pyramid8 p = build_pyramid(make_level(4, 1, {0, 1, 10, 255}));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], make_level(2, 1, {1, 133}));  // (0+1+1)>>1 = 1, (10+255+1)>>1 = 133
  EXPECT_EQ(p[2], make_level(1, 1, {67}));      // (1+133+1)>>1 = 67
}

TEST(MipgenTest, PyramidOfASingleColumnRepeatsTheColumn) {
  const Pyramid8 p = build_pyramid(make_level(1, 4, {0, 1, 10, 255}));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], make_level(1, 2, {1, 133}));
  EXPECT_EQ(p[2], make_level(1, 1, {67}));
}

TEST(MipgenTest, PyramidOfANonSquareTexture) {
  // 4 x 2 -> 2 x 1 -> 1 x 1; the last step repeats the row.
  const Pyramid8 p = build_pyramid(make_level(4, 2,
                                              {0, 4, 8, 9,  //
                                               2, 6, 9, 9}));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], make_level(2, 1, {3, 9}));  // (12+2)>>2 = 3, (35+2)>>2 = 9
  EXPECT_EQ(p[2], make_level(1, 1, {6}));     // (2*3 + 2*9 + 2)>>2 = 6
}

TEST(MipgenTest, PyramidRejectsNonPowerOfTwoSides) {
  EXPECT_THROW(build_pyramid(Level8(3, 4)), std::invalid_argument);
  EXPECT_THROW(build_pyramid(Level8(2048, 1)), std::invalid_argument);
}

// ---- the streaming model ------------------------------------------------------------------

// One frame of `level0` through the stream: the writes read back through Geometry::cell
// must be build_pyramid, every cell of the layout written exactly once, and every write in
// the documented order.
void expect_stream_is_pyramid(const MipgenConfig& cfg, const Level8& level0) {
  SCOPED_TRACE(::testing::Message() << (1u << cfg.log2_w) << " x " << (1u << cfg.log2_h)
                                    << (cfg.interlaced ? " interlaced" : "") << " plane "
                                    << cfg.plane << "/" << cfg.planes);
  const std::vector<CellWrite> writes = mipgen_frame(cfg, level0);
  const Geometry g(cfg.log2_w, cfg.log2_h, cfg.planes);
  BankMemory mem(g);
  for (const CellWrite& w : writes) {
    ASSERT_EQ(w.cell, g.cell(w.level, w.x, w.y, cfg.plane));
    mem.write(w);
  }
  EXPECT_EQ(mem.read_pyramid(cfg.plane), build_pyramid(level0));
  EXPECT_EQ(mem.cells_not_written_once(cfg.plane), 0u);
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
  EXPECT_EQ(w.back().value, round_box_sum(99 + 20 + 30 + 40));
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
