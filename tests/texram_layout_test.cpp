// The TEXRAM bank layout (000 Fig. 2): the eight texels of every trilinear footprint come out
// of eight different banks, and every stored cell has an address of its own.
#include <gtest/gtest.h>

#include <bitset>
#include <set>

#include "texram/layout.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram {
namespace {

SamplerConfig trilinear(Border border) {
  SamplerConfig c;
  c.filter = Filter::kTrilinear;
  c.border_u = c.border_v = border;
  return c;
}

// Bank mask of an access, checking each tap's cell is the one its bank reads.
std::bitset<8> banks_read(const SamplePlan& plan) {
  std::bitset<8> mask;
  for (size_t b = 0; b < 8; ++b) mask[b] = plan.bank_address[b].has_value();
  return mask;
}

// Every footprint position of every level pair of a 1024 x 1024 pyramid, at the first and the
// last sub-texel position with that footprint (the two ends can select different footprints
// in the next level): all eight banks, each once.
TEST(TexramLayoutTest, EveryTrilinearFootprintOf1024ReadsEveryBankExactlyOnce) {
  const Geometry g(10, 10);
  const SamplerConfig config = trilinear(Border::kWrap);
  uint64_t footprints = 0;
  for (int l = 0; l + 1 < g.levels(); ++l) {
    const int32_t half_level = 1 << (7 + l);  // 0.5 level-l texels in level-0 SQ16.8 units
    for (uint32_t y0 = 0; y0 < g.texel_height(l); ++y0) {
      for (uint32_t x0 = 0; x0 < g.texel_width(l); ++x0) {
        for (int end = 0; end < 2; ++end) {
          // Footprint origin x0 at level l: u_l in [x0 + 0.5, x0 + 1.5).
          const int32_t first_u = static_cast<int32_t>(2 * x0 + 1) * half_level;
          const int32_t first_v = static_cast<int32_t>(2 * y0 + 1) * half_level;
          const int32_t last = end ? 2 * half_level - (1 << l) : 0;  // one level-l LSB short
          Request r{first_u + last, first_v + last, (l << 8) + 128, 0};
          const SamplePlan plan = plan_sample(g, config, r);
          ASSERT_EQ(plan.levels_read, 2);
          ASSERT_EQ(plan.level[0], l);
          ASSERT_EQ(plan.taps[0][0].x, x0);
          ASSERT_EQ(plan.taps[0][0].y, y0);
          ASSERT_EQ(banks_read(plan).count(), 8u)
              << "level " << l << " footprint (" << x0 << ", " << y0 << ")";
          for (int j = 0; j < 2; ++j) {
            for (const Tap& t : plan.taps[static_cast<size_t>(j)]) {
              ASSERT_EQ(plan.bank_address[t.cell.bank], t.cell.address);
            }
          }
          ++footprints;
        }
      }
    }
  }
  std::cout << footprints << " footprints checked\n";
  EXPECT_EQ(footprints, 2u * (1024 * 1024 + 512 * 512 + 256 * 256 + 128 * 128 + 64 * 64 + 32 * 32 +
                              16 * 16 + 64 + 16 + 4));
}

// Whether every tap of `plan` inside the texture reads the cell that holds its texel: the
// texel lies in its level, the tap's cell is one holding it (its grid position, or a replica
// where the level is stored wider than its grid: stored cell x holds grid position x mod
// width), and that cell is the one the access reads in its bank; and no bank is read for
// nothing.
testing::AssertionResult taps_read_their_texels(const Geometry& g, const SamplePlan& plan) {
  std::bitset<8> wanted;
  for (int j = 0; j < plan.levels_read; ++j) {
    const int l = plan.level[static_cast<size_t>(j)];
    for (int k = 0; k < plan.taps_per_level; ++k) {
      const Tap& t = plan.taps[static_cast<size_t>(j)][static_cast<size_t>(k)];
      if (t.outside) continue;
      auto failure = [&] {
        return testing::AssertionFailure()
               << "level " << l << " tap " << k << " texel (" << t.x << ", " << t.y << ") cell "
               << t.cell.bank << ":" << t.cell.address << ": ";
      };
      if (t.x >= g.texel_width(l) || t.y >= g.texel_height(l))
        return failure() << "not in the level";
      const uint32_t gx = g.block_grid() ? t.x / 4 : t.x;
      const uint32_t gy = g.block_grid() ? t.y / 4 : t.y;
      bool holds = false;
      for (uint32_t sy = gy; sy < g.stored_height(l); sy += g.grid_height(l)) {
        for (uint32_t sx = gx; sx < g.stored_width(l); sx += g.grid_width(l)) {
          holds = holds || g.cell(l, sx, sy) == t.cell;
        }
      }
      if (!holds) return failure() << "that cell does not hold the texel";
      if (plan.bank_address[t.cell.bank] != t.cell.address) {
        return failure() << "its bank reads another address";
      }
      wanted[t.cell.bank] = true;
    }
  }
  if (banks_read(plan) != wanted) {
    return testing::AssertionFailure()
           << "banks read " << banks_read(plan) << ", taps need " << wanted;
  }
  return testing::AssertionSuccess();
}

// In every border mode, on textures of every shape, at every position around the edges: no
// bank is asked for two cells (plan_sample throws if one is), and every tap inside the texture
// reads the cell that holds its texel.
TEST(TexramLayoutTest, EveryBorderModeReadsEachBankAtMostOnce) {
  for (bool blocks : {false, true}) {
    for (int lw : {0, 1, 2, 3, 5}) {
      for (int lh : {0, 1, 3, 4}) {
        const Geometry g(lw, lh, blocks ? 4 : 1, blocks);
        for (Border b : {Border::kWrap, Border::kClamp, Border::kBorder, Border::kMirror}) {
          for (Filter f : {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear}) {
            SamplerConfig config = trilinear(b);
            config.filter = f;
            for (int32_t lambda = -256; lambda <= (g.levels() + 1) * 256; lambda += 64) {
              for (int32_t u = -3 * 256 * 33; u <= 3 * 256 * 33; u += 97) {
                const int32_t v = (u * 7) % (256 * 40);
                SamplePlan plan;
                ASSERT_NO_THROW(plan = plan_sample(g, config, Request{u, v, lambda, 0}))
                    << "blocks " << blocks << " " << lw << "x" << lh << " " << name(b) << " "
                    << name(f);
                ASSERT_TRUE(taps_read_their_texels(g, plan))
                    << "blocks " << blocks << " " << lw << "x" << lh << " " << name(b) << " "
                    << name(f) << " u " << u << " v " << v << " lambda " << lambda;
              }
            }
          }
        }
      }
    }
  }
}

// Each stored cell of each level and plane has its own (bank, address), inside the bank.
TEST(TexramLayoutTest, CellsAreDistinctAndInsideTheBanks) {
  for (auto [lw, lh, planes, blocks] :
       {std::tuple{10, 10, 1, false}, std::tuple{10, 3, 4, false}, std::tuple{0, 0, 1, false},
        std::tuple{9, 10, 4, true}, std::tuple{2, 0, 4, true}}) {
    const Geometry g(lw, lh, planes, blocks);
    std::set<std::pair<unsigned, uint32_t>> seen;
    uint64_t cells = 0;
    for (int l = 0; l < g.levels(); ++l) {
      for (uint32_t y = 0; y < g.stored_height(l); ++y) {
        for (uint32_t x = 0; x < g.stored_width(l); ++x) {
          for (int p = 0; p < planes; ++p) {
            const BankCell c = g.cell(l, x, y, p);
            ASSERT_LT(c.address, g.bank_cells());
            ASSERT_EQ(c.bank, bank_of(l, x, y));
            ASSERT_TRUE(seen.insert({c.bank, c.address}).second) << "cell reused at level " << l;
            ++cells;
          }
        }
      }
    }
    EXPECT_EQ(seen.size(), cells);
    EXPECT_LT(int64_t{g.bank_cells()}, int64_t{1} << formats::kBankAddr.width());
  }
}

TEST(TexramLayoutTest, LargestTextureFitsTheBankAddress) {
  const Geometry g(10, 10, formats::kPlanes);
  EXPECT_EQ(g.bank_cells(), 4u * 279621u);  // even levels: 512^2 + 128^2 + 32^2 + 8^2 + 2^2 + 1
  EXPECT_LT(g.bank_cells(), 1u << formats::kBankAddr.width());
}

}  // namespace
}  // namespace tmu::texram
