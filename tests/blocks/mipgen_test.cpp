// What is the mipmap generator's own (000 §12; the conformance suite checks what every block
// shares): one write per clock, the cells the rtl writes read back through the layout as
// build_pyramid (a driver filling every plane and changing the format between frames, up to
// 1024 x 1024), the tie frame's contract, and the stimulus the unit cannot take rejected by
// golden with its reason. The bank address unit it computes its cells with has its own test
// (bank_address_test.cpp).
#include <gtest/gtest.h>
#include <verilated.h>

#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "blocks/mipgen/mipgen_block.hpp"
#include "formats/formats.hpp"
#include "texram/layout.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"

namespace tmu::tb {
namespace {

texram::Level8 random_frame(int log2_w, int log2_h, uint64_t seed) {
  std::mt19937_64 rng(seed);
  texram::Level8 l(1u << log2_w, 1u << log2_h);
  for (uint8_t& t : l.texels) t = static_cast<uint8_t>(rng());
  return l;
}

RunResult run(const std::string& level, const std::vector<Txn>& items) {
  return MipgenBlock().engine(level)->run(items, RunOptions{});
}

// One write per clock: without stalls the rtl never idles between writes (an item is taken
// in the cycle the previous item's last write leaves), over whole frames; nor does the hls
// module.
TEST(MipgenTest, OneWritePerClock) {
  for (const auto& [lw, lh, il] : {std::tuple{5, 4, false}, std::tuple{4, 5, true},
                                   std::tuple{0, 0, false}, std::tuple{10, 0, true}}) {
    const texram::MipgenConfig cfg{lw, lh, il, 1, 0};
    SCOPED_TRACE(mipgen_format_text(cfg));
    std::vector<Txn> items = mipgen_items(cfg, random_frame(lw, lh, 1));
    while (items.size() < 2000) {
      for (const Txn& t : mipgen_frame_items(random_frame(lw, lh, items.size()), il)) {
        items.push_back(t);
      }
    }
    const RunResult rtl = run("rtl", items);
    const RunResult hls = run("hls", items);
    ASSERT_TRUE(rtl.error.empty() && hls.error.empty()) << rtl.error << hls.error;
    ASSERT_EQ(rtl.outputs, hls.outputs);
    ASSERT_FALSE(rtl.outputs.empty());
    const size_t writes = rtl.outputs.size();
    EXPECT_EQ(rtl.output_cycles.back() - rtl.output_cycles.front(), writes - 1);
    EXPECT_EQ(hls.output_cycles.back() - hls.output_cycles.front(), writes - 1);
  }
}

// A driver fills the planes of several textures through one generator, writing each plane's
// format between frames: the rtl's writes of each frame, stored in that texture's bank image,
// read back through Geometry::cell as build_pyramid, every cell of the layout (replicas
// included) written exactly once.
TEST(MipgenTest, RtlWritesReadBackAsThePyramid) {
  struct Texture {
    int lw, lh;
    bool interlaced;
    int planes;
  };
  const std::vector<Texture> textures = {{0, 0, false, 1}, {10, 0, true, 4}, {0, 10, true, 1},
                                         {7, 3, true, 4},  {3, 7, false, 4}, {6, 6, true, 1}};
  std::vector<Txn> items;
  std::vector<size_t> writes_of_frame;  // golden's count, to split the rtl's writes
  for (const Texture& t : textures) {
    const texram::Level8 level0 = random_frame(t.lw, t.lh, 77);
    for (int plane = 0; plane < t.planes; ++plane) {
      const texram::MipgenConfig cfg{t.lw, t.lh, t.interlaced, t.planes, plane};
      for (const Txn& item : mipgen_items(cfg, level0)) items.push_back(item);
      writes_of_frame.push_back(texram::mipgen_frame(cfg, level0).size());
    }
  }
  const RunResult r = run("rtl", items);
  ASSERT_TRUE(r.error.empty()) << r.error;
  size_t next = 0, frame = 0;
  for (const Texture& t : textures) {
    const texram::Level8 level0 = random_frame(t.lw, t.lh, 77);
    texram::BankMemory mem(texram::Geometry(t.lw, t.lh, t.planes));
    for (int plane = 0; plane < t.planes; ++plane) {
      SCOPED_TRACE(mipgen_format_text({t.lw, t.lh, t.interlaced, t.planes, plane}));
      const size_t n = writes_of_frame[frame++];
      ASSERT_LE(next + n, r.outputs.size());
      for (size_t k = next; k < next + n; ++k) mem.write(mipgen_txn_write(r.outputs[k]));
      next += n;
      EXPECT_EQ(mem.read_pyramid(plane), texram::build_pyramid(level0));
      EXPECT_EQ(mem.cells_not_written_once(plane), 0u);
    }
  }
  EXPECT_EQ(next, r.outputs.size());
}

TEST(MipgenTest, RtlWritesReadBackAsThePyramidAt1024x1024) {
  const texram::Level8 level0 = random_frame(10, 10, 78);
  const RunResult r = run("rtl", mipgen_items({10, 10, true, 4, 3}, level0));
  ASSERT_TRUE(r.error.empty()) << r.error;
  texram::BankMemory mem(texram::Geometry(10, 10, 4));
  for (const Txn& t : r.outputs) mem.write(mipgen_txn_write(t));
  EXPECT_EQ(mem.read_pyramid(3), texram::build_pyramid(level0));
  EXPECT_EQ(mem.cells_not_written_once(3), 0u);
}

// The directed tie frame: every box of every level is a rounding tie (its mean halfway), and
// the top is 127.5 rounded up.
TEST(MipgenTest, TieFrameRoundsEveryBoxHalfUp) {
  for (const auto& [lw, lh] :
       {std::pair{10, 10}, std::pair{10, 0}, std::pair{0, 9}, std::pair{4, 7}, std::pair{1, 1}}) {
    const texram::Level8 frame = mipgen_tie_frame(lw, lh);
    texram::MipgenStream s({lw, lh, false, 1, 0});
    std::vector<texram::CellWrite> w;
    size_t boxes = 0, ties = 0;
    for (const texram::MipgenInput& in : texram::mipgen_source(frame, false)) {
      s.step(in, w);
      for (const texram::BoxSum& b : s.last_box_sums()) {
        ++boxes;
        ties += b.sum % (4u << b.frac_bits) == (2u << b.frac_bits);
      }
    }
    EXPECT_EQ(ties, boxes) << lw << " x " << lh;
    EXPECT_EQ(texram::build_pyramid(frame).back().at(0, 0), 128);
  }
}

// What the unit cannot take is a golden error that says why, and no timed run starts on it.
TEST(MipgenTest, RejectsWhatADriverMustNotSend) {
  const texram::MipgenConfig cfg{2, 1, false, 1, 0};
  const std::vector<Txn> frame = mipgen_items(cfg, random_frame(2, 1, 5));
  const auto golden_error = [](const std::vector<Txn>& items) {
    return run("golden", items).error;
  };

  std::vector<Txn> mid_frame(frame.begin(), frame.begin() + 4);
  mid_frame.push_back(mipgen_config_item({1, 1, false, 1, 0}));
  EXPECT_EQ(golden_error(mid_frame),
            "mipgen: the format 2 x 2, plane 0 of 1 written at texel (3, 0) of a 4 x 2, plane 0 "
            "of 1 frame (a driver writes the format between frames)");
  EXPECT_THROW(run("rtl", mid_frame), std::runtime_error);

  EXPECT_EQ(golden_error({frame.begin() + 1, frame.end()}),
            "mipgen: a texel before the first configuration item");

  std::vector<Txn> too_wide = frame;
  too_wide.push_back(mipgen_config_item({11, 0, false, 1, 0}));
  EXPECT_NE(golden_error(too_wide).find("mipgen: the format 2048 x 1, plane 0 of 1 is not the "
                                        "unit's: MipgenStream: log2 sizes must be 0..10"),
            std::string::npos)
      << golden_error(too_wide);

  std::vector<Txn> no_such_plane = frame;
  no_such_plane.push_back(mipgen_config_item({2, 1, false, 1, 2}));
  EXPECT_NE(golden_error(no_such_plane).find("plane 2 outside 0..0"), std::string::npos)
      << golden_error(no_such_plane);

  // Between frames, a new format is taken.
  std::vector<Txn> two = frame;
  for (const Txn& t : mipgen_items({1, 1, true, 4, 2}, random_frame(1, 1, 6))) two.push_back(t);
  EXPECT_EQ(golden_error(two), "");
}

}  // namespace
}  // namespace tmu::tb
