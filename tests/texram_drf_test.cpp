// The TEXRAM chip's description register files (golden/texram/chip/drf.hpp): a DRF loaded
// through the write port is the DRF that was packed; the port ignores what a DRF cannot hold;
// chains follow the links, and a cycle or a bad lead is refused with the DRFs named.
#include <gtest/gtest.h>

#include <random>

#include "texram/chip/drf.hpp"

namespace tmu::texram::chip {
namespace {

Drf random_drf(std::mt19937& rng, bool cube) {
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  Drf d;
  d.base = rng() % (1u << formats::kBankAddr.width());
  d.log2_w = pick(11);
  d.log2_h = pick(11);
  d.sampler.kind = static_cast<TexelKind>(pick(5));
  d.sampler.single_channel = pick(4);
  d.sampler.filter = static_cast<Filter>(pick(3));
  d.sampler.border_u = static_cast<Border>(pick(4));
  d.sampler.border_v = static_cast<Border>(pick(4));
  d.sampler.border_rgba = static_cast<uint32_t>(rng());
  d.sampler.combine = static_cast<Combine>(pick(3));
  d.sampler.constant_rgba = static_cast<uint32_t>(rng());
  d.sampler.addressing = static_cast<Addressing>(pick(2));
  d.op = static_cast<DrfOp>(pick(kDrfOps));
  d.link = pick(8);
  d.takes_coords = pick(2) != 0;
  d.footprint = pick(2) != 0;
  d.log2_max_probes = pick(8);
  d.q_rule = static_cast<footprint::QRule>(pick(2));
  d.cube = cube;
  if (cube) {
    for (uint32_t& b : d.face_base) b = rng() % (1u << formats::kBankAddr.width());
  }
  return d;
}

TEST(TexramDrfTest, WritePortLoadsWhatWasPacked) {
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const int n = 1 + i % kDrfs;
    const Drf want = random_drf(rng, n == kCubeDrf && i % 2 == 0);
    DrfFile file{};
    for (const DrfWrite& w : drf_writes(n, want)) apply(file, w);
    ASSERT_EQ(file[static_cast<size_t>(n - 1)], want) << "DRF " << n << ", draw " << i;
    for (int m = 1; m <= kDrfs; ++m) {
      if (m == n) continue;
      ASSERT_EQ(file[static_cast<size_t>(m - 1)], Drf{}) << "DRF " << m << " changed";
    }
  }
}

TEST(TexramDrfTest, WritePortIgnoresWhatADrfCannotHold) {
  DrfFile file{};
  apply(file, {1, static_cast<uint8_t>(DrfFieldId::kBase), 0xFFFFFFFFu});
  EXPECT_EQ(file[0].base, (1u << formats::kBankAddr.width()) - 1);  // 21 bits kept
  apply(file, {0, static_cast<uint8_t>(DrfFieldId::kBase), 5});     // no DRF 0
  apply(file, {2, static_cast<uint8_t>(DrfFieldId::kFace0), 5});    // faces are DRF 7's
  apply(file, {7, 11, 5});                                          // no field 11
  apply(file, {7, 15, 5});
  EXPECT_EQ(file[1], Drf{});
  EXPECT_EQ(file[6], Drf{});
  apply(file, {7, static_cast<uint8_t>(static_cast<int>(DrfFieldId::kFace0) + 5), 0x1234});
  EXPECT_EQ(file[6].face_base[5], 0x1234u);
  // The control word's op, link and coordinate bit, and nothing above bit 8.
  apply(file,
        {3, static_cast<uint8_t>(DrfFieldId::kControl), 0xFFFFFE00u | 4u | 5u << 3 | 1u << 6});
  EXPECT_EQ(file[2].op, DrfOp::kEmit);
  EXPECT_EQ(file[2].link, 5);
  EXPECT_TRUE(file[2].takes_coords);
  EXPECT_EQ(file[2].sampler.combine, Combine::kOne);
}

TEST(TexramDrfTest, ChainsFollowTheLinksAndRefuseCycles) {
  DrfFile file{};
  file[0].link = 3;  // 1 -> 3 -> 6
  file[2].link = 6;
  EXPECT_EQ(chain(file, 1), (std::vector<int>{1, 3, 6}));
  EXPECT_EQ(chain(file, 6), (std::vector<int>{6}));
  file[5].link = 3;  // 6 -> 3: a cycle
  try {
    chain(file, 1);
    ADD_FAILURE() << "no error for a cycle";
  } catch (const ProgramError& e) {
    EXPECT_STREQ(e.what(), "link cycle: DRF 1 -> 3 -> 6 -> 3");
  }
  EXPECT_THROW(chain(file, 0), ProgramError);
  EXPECT_THROW(chain(file, 8), ProgramError);
  // The longest chain without a cycle visits all seven.
  DrfFile all{};
  for (int n = 1; n < kDrfs; ++n) all[static_cast<size_t>(n - 1)].link = n + 1;
  EXPECT_EQ(chain(all, 1).size(), static_cast<size_t>(kMaxSteps));
  all[2].cube = true;
  EXPECT_THROW(check_program(all, {1}), ProgramError);  // a cube map outside DRF 7
  all[2].cube = false;
  all[6].cube = true;
  EXPECT_NO_THROW(check_program(all, {1}));
  // A detail map: 2 -> offsets 3 -> detail 4, or the chip could not find its maps.
  all[1].detail = true;
  EXPECT_THROW(check_program(all, {1}), ProgramError);
  all[2].op = DrfOp::kOffsets;
  EXPECT_THROW(check_program(all, {1}), ProgramError);
  all[3].op = DrfOp::kDetail;
  EXPECT_NO_THROW(check_program(all, {1}));
  all[1].op = DrfOp::kEmit;  // only a texture or reflectance map has a detail map
  EXPECT_THROW(check_program(all, {1}), ProgramError);
}

}  // namespace
}  // namespace tmu::texram::chip
