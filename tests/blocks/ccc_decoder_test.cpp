// What is the CCC decoder's own (000 §3, Fig. 5; the conformance suite,
// tests/conformance_test.cpp, checks what every block shares): the worked example of
// rtl/ccc/tmu_ccc_decoder.sv's header through every engine, one texel per clock, a whole
// texture through decode_with_engine (what `texsim ccc decode` runs) equal to golden's
// decode_image at every level, and a decode of a CLUT entry never written refused by golden.
#include "ccc/ccc_decoder.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "blocks/ccc_decoder/ccc_decoder_block.hpp"
#include "ccc/ccc_encoder.hpp"
#include "common/test_patterns.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using D = desc::ccc_decoder;

// Block 0x0A0B_0002, texel 1 -> decision bit 1 -> index 0x0B -> CLUT[0x0B]; texel 0 -> bit 0 ->
// index 0x0A. The two entries are written after the load, just before the decodes.
TEST(CccDecoderTest, HeaderExample) {
  const CccDecoderBlock block;
  std::vector<Txn> items = block.setup_items();
  items.push_back(clut_write_item(0x0A, 0x112233));
  items.push_back(clut_write_item(0x0B, 0xAABBCC));
  items.push_back(decode_item(0x0A0B0002u, 1));
  items.push_back(decode_item(0x0A0B0002u, 0));
  testing::expect_outputs(block, items, D::out_rgb, {0xAABBCCu, 0x112233u});
}

// One texel per clock: without bubbles or stalls every item (decode or CLUT write) takes one
// cycle, plus the output register and the harness's 16 drain cycles (the hls model's
// registered ready one more, after reset).
TEST(CccDecoderTest, OneTexelPerClock) {
  testing::expect_full_rate(CccDecoderBlock(), 10'000, {{"rtl", 1 + 16}, {"hls", 2 + 16}});
}

// A texture whose sides are not multiples of 4 (edge blocks padded), decoded texel by texel
// through each level's engine, is golden's decode_image.
TEST(CccDecoderTest, WholeTextureThroughEveryEngine) {
  const ccc::Texture tex = ccc::encode(patterns::smooth_field(37, 23, 4));
  const ImageRgb8 want = ccc::decode_image(tex);
  for (const std::string level : {"golden", "hls", "rtl"}) {
    const auto engine = CccDecoderBlock().engine(level);
    RunResult run;
    EXPECT_EQ(decode_with_engine(tex, *engine, &run), want) << level;
    EXPECT_TRUE(run.error.empty()) << level << ": " << run.error;
  }
}

// The CLUT has no reset: golden refuses a decode of an entry no write has set, naming it,
// instead of guessing a colour the RTL does not have.
TEST(CccDecoderTest, DecodeOfAnUnwrittenEntryIsRefused) {
  const std::vector<Txn> items = {clut_write_item(5, 0x123456),
                                  decode_item(0x05060000u, 0),   // index a = 5: written
                                  decode_item(0x05060001u, 0)};  // index b = 6: never written
  const RunResult r = CccDecoderBlock().engine("golden")->run(items, RunOptions{});
  EXPECT_NE(r.error.find("a decode of CLUT entry 6 before any write to it"), std::string::npos)
      << r.error;
}

}  // namespace
}  // namespace tmu::tb
