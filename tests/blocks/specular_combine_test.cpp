// What is the specular combine's own (000 §7 eq. 6, §8 eq. 7; the conformance suite,
// tests/conformance_test.cpp, checks what every block shares): the golden rule against a plain
// double reference for every (d, e, r), the worked example of rtl/texram/tmu_specular_combine.sv's
// header and the items the renderer builds through every engine, and one colour per clock.
#include "texram/specular_combine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "blocks/specular_combine/specular_combine_block.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

// The worked example of rtl/texram/tmu_specular_combine.sv's header, at compile time.
static_assert(texram::specular_combine(0xF0804020u, 0x80FF40FFu, 0x40FFFF00u) == 0xFFFF8020u);
static_assert(texram::specular_combine(0x12345678u, 0xFFFFFFFFu, 0x000000FFu) == 0x12345678u);

// min(255, d + round(e r / 255)) in double precision.
uint32_t reference(uint32_t d, uint32_t e, uint32_t r) {
  const double sum = d + std::round(static_cast<double>(e) * r / 255.0);
  return static_cast<uint32_t>(std::min(255.0, sum));
}

// The golden rule against the double reference for every e, r and d (2^24 triples), each
// triple in R, in G (with e, r swapped) and in B (with d mirrored), and the alpha from D
// whatever E's and R's alphas are.
TEST(SpecularCombineTest, EveryTripleMatchesTheDoubleReference) {
  uint64_t failures = 0;
  for (uint32_t e = 0; e < 256; ++e) {
    for (uint32_t r = 0; r < 256; ++r) {
      // mul255 itself: e r / 255 is never exactly half way (255 is odd).
      ASSERT_EQ(texram::mul255(e, r), static_cast<uint32_t>(std::lround(e * r / 255.0)))
          << "e " << e << " r " << r;
      for (uint32_t d = 0; d < 256; ++d) {
        const uint32_t alpha = (d + e + r) & 0xFFu;
        const uint32_t dw = d << 24 | d << 16 | (255 - d) << 8 | alpha;
        const uint32_t ew = e << 24 | r << 16 | e << 8 | (~alpha & 0xFFu);
        const uint32_t rw = r << 24 | e << 16 | r << 8 | (alpha ^ 0x5Au);
        const uint32_t want = reference(d, e, r) << 24 | reference(d, r, e) << 16 |
                              reference(255 - d, e, r) << 8 | alpha;
        const uint32_t got = texram::specular_combine(dw, ew, rw);
        if (got != want && ++failures <= 10) {
          ADD_FAILURE() << std::hex << "d " << d << " e " << e << " r " << r << ": got 0x" << got
                        << ", want 0x" << want;
        }
      }
    }
  }
  EXPECT_EQ(failures, 0u);
}

// The header's example and a full-reflectance sum, built as the renderer builds its items,
// through every engine.
TEST(SpecularCombineTest, HeaderExampleThroughEveryEngine) {
  const SpecularCombineBlock block;
  const std::vector<Txn> items = {specular_combine_item(0xF0804020u, 0x80FF40FFu, 0x40FFFF00u),
                                  specular_combine_item(0x10203040u, 0xFFFFFFFFu, 0xFFFFFF00u)};
  testing::expect_outputs(block, items, desc::specular_combine::out_colour,
                          {0xFFFF8020u, 0xFFFFFF40u});
}

// One colour per clock: without bubbles or stalls the rtl takes the items, its latency (2
// cycles) and the harness's 16 drain cycles; the hls model keeps the same rate.
TEST(SpecularCombineTest, OneColourPerClock) {
  testing::expect_full_rate(SpecularCombineBlock(), 20'000, {{"rtl", 2 + 16}, {"hls", 2 + 16}},
                            false);
}

}  // namespace
}  // namespace tmu::tb
