// What is fire's e^-v table's own (002 §4.2.2; the conformance suite, tests/conformance_test.cpp,
// reads every entry of the RTL's table against golden's): the RTL's integer construction,
// replayed in C++, gives golden's double-precision entries with a margin its error cannot
// cross; and the worked example of rtl/perlin/tmu_material_fire.sv's header.
#include <gtest/gtest.h>

#include <cmath>

#include "blocks/material_fire/material_fire_block.hpp"
#include "perlin/materials.hpp"

namespace tmu::tb {
namespace {

using D = desc::material_fire;

// The construction of tmu_material_fire.sv's constant function, step by step, gives golden's
// entries, and every exact value lies at least 0.001 from a rounding tie: the margin the
// integer evaluation's error (below 2^-26 at 48 fraction bits) cannot cross.
TEST(MaterialFireTest, IntegerConstructionIsGoldens) {
  __extension__ typedef unsigned __int128 u128;
  constexpr int kP = 48;
  u128 term = u128{1} << kP, e1 = 0;
  for (int n = 0; n < 12; ++n) {
    e1 = n % 2 == 0 ? e1 + term : e1 - term;
    term /= static_cast<u128>(32 * (n + 1));
  }
  u128 acc = u128{1} << kP;
  const u128 half = u128{1} << (kP - 1);
  for (uint32_t k = 0; k < perlin::kFireTableEntries; ++k) {
    const auto entry = static_cast<uint32_t>(((acc << 12) + half) >> kP);
    ASSERT_EQ(entry, perlin::fire_entry(k)) << "entry " << k;
    const double exact = std::exp(-static_cast<double>(k) / 32.0) * 4096.0;
    EXPECT_GT(std::abs(exact - std::floor(exact) - 0.5), 0.001) << "entry " << k;
    acc = (acc * e1 + half) >> kP;
  }
}

// The header's example on golden and rtl: k = 32 (v = 1.0), e^-1 2^12 = 1506.8, entry 1507.
TEST(MaterialFireTest, HeaderExample) {
  const MaterialFireBlock block;
  const std::vector<Txn> items = {channel_item(D::table(), "in", {32})};
  for (const std::string level : {"golden", "rtl"}) {
    const RunResult r = block.engine(level)->run(items, RunOptions{});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs.size(), 1u) << level;
    EXPECT_EQ(r.outputs[0].f[D::out_entry], 1507u) << level;
  }
}

}  // namespace
}  // namespace tmu::tb
