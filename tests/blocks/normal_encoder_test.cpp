// What is the normal encoder's own (001 §4.1; the conformance suite, tests/conformance_test.cpp,
// checks what every block shares): the worked example of rtl/deflect/tmu_normal_encoder.sv's
// header through every engine, one normal per clock, the directed items reaching every table
// index the ratios can reach, widths no variant verilates through hls, and which levels the
// block has at those widths.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "blocks/normal_encoder/normal_encoder_block.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using deflect::EncoderConfig;
using D = desc::normal_encoder;

NormalEncoderBlock block_of(int seed_bits, int lut_exp, int lut_mant) {
  BlockOptions o;
  o.encoder.seed_bits = seed_bits;
  o.encoder.lut_exp = lut_exp;
  o.encoder.lut_mant = lut_mant;
  return NormalEncoderBlock(o);
}

// The header's example: N = (0.5, 0, 1.0) gives phi 38 (atan 0.5 = 37.8 steps), theta +0.
TEST(NormalEncoderTest, HeaderExample) {
  const NormalEncoderBlock block;
  testing::expect_outputs(block, {normal_item(8192, 0, 16384)}, D::out_phi, {38u});
  testing::expect_outputs(block, {normal_item(8192, 0, 16384)}, D::out_theta, {0u});
}

// One normal per clock: without bubbles or stalls the rtl takes the items, its latency (8
// cycles) and the harness's 16 drain cycles; the hls model keeps the same rate.
TEST(NormalEncoderTest, OneNormalPerClock) {
  testing::expect_full_rate(NormalEncoderBlock(), 20'000, {{"rtl", 8 + 16}, {"hls", 8 + 16}});
}

// The directed items alone reach every angle-table index a ratio can reach, for phi and for
// theta, and every seed-table index of both dividers. With E > 1 the first E - 1 levels'
// entries of m < 2^(M-2) are dead (the leading pair is never zero there): 104 of the default's
// 128 entries are reachable; the linear index reaches all 128.
TEST(NormalEncoderTest, DirectedItemsReachEveryTableIndex) {
  for (const NormalEncoderBlock& block : {block_of(7, 4, 5), block_of(7, 1, 7)}) {
    const EncoderConfig& c = block.config();
    const std::set<uint32_t> reachable = reachable_angle_indices(c);
    EXPECT_EQ(reachable.size(), c.lut_exp == 1 ? 128u : 104u);
    const deflect::NormalEncoder enc(c);
    std::set<uint32_t> angle[2], seed[2];
    for (const Txn& item : block.directed_items()) {
      deflect::EncoderTrace t;
      const int16_t x = normal_x(item), y = normal_y(item), z = normal_z(item);
      enc.encode(x, y, z, &t);
      if (t.t_phi != 0) angle[0].insert(deflect::angle_index(c, t.t_phi));  // t = 0: no read
      if (t.t_theta != 0) angle[1].insert(deflect::angle_index(c, t.t_theta));
      const auto sq = [](int16_t v) { return static_cast<uint32_t>(int32_t{v} * int32_t{v}); };
      seed[0].insert(encoder_seed_index(std::max(sq(x), sq(z)), c.seed_bits));
      seed[1].insert(encoder_seed_index(std::max(sq(y), sq(x) + sq(z)), c.seed_bits));
    }
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(angle[k], reachable) << (k ? "theta" : "phi");
      EXPECT_EQ(seed[k].size(), size_t{1} << c.seed_bits) << (k ? "theta" : "phi");
    }
  }
}

// The extreme widths (S = 12, E = 8, M = 10; S = 2 with E = M = 2), which no variant
// verilates, through the hls model: the directed generator still reaches every case.
TEST(NormalEncoderTest, ExtremeWidthsGoldenVsHls) {
  for (const NormalEncoderBlock& block : {block_of(12, 8, 10), block_of(2, 2, 2)}) {
    std::stringstream log;
    const CosimResult r = run_cosim(block, testing::cosim_options(29, 5'000, {"hls"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "not hit: " << name;
  }
}

// Widths without a verilated model have no rtl level (hls and icarus run them), and asking for
// one names the levels there are; the reproduce line keeps the widths. A variant's widths have
// their rtl level.
TEST(NormalEncoderTest, UnverilatedWidthsHaveNoRtlLevel) {
  const NormalEncoderBlock block = block_of(8, 3, 6);
  EXPECT_EQ(block.repro_options(), "--encoder 8,3,6");
  EXPECT_EQ(block.levels(), (std::vector<std::string>{"golden", "hls", "icarus"}));
  try {
    (void)block.engine("rtl");
    FAIL() << "an rtl engine for widths that are not verilated";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no engine 'rtl' (levels: golden, hls, icarus)"), std::string::npos)
        << what;
  }
  const NormalEncoderBlock linear = block_of(7, 1, 7);
  EXPECT_EQ(linear.variant(), "e1m7");
  EXPECT_EQ(linear.repro_options(), "--encoder 7,1,7");
  const std::vector<std::string> have = linear.levels();
  EXPECT_NE(std::find(have.begin(), have.end(), "rtl"), have.end());
}

}  // namespace
}  // namespace tmu::tb
