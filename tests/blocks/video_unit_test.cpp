// The video unit's own tests (the conformance suite runs golden = hls = rtl on the directed and
// random stimulus of both builds): a video runs on past the wrap of its 16-bit frame tags.
#include "texram/video/video_unit.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "blocks/video_unit/video_unit_block.hpp"
#include "texram/mipmap.hpp"

namespace tmu::tb {
namespace {
namespace video = texram::video;
using D = desc::video_unit;

// The items of a run, with the golden unit beside them to know when the rows are idle.
class Items {
 public:
  explicit Items(const Txn& cfg) { configure(cfg); }
  void configure(const Txn& cfg) {
    unit_.configure(video_unit_config(cfg));
    items.push_back(cfg);
  }
  void texel(const video::VideoItem& it) {
    unit_.receive(it);
    items.push_back(channel_item(D::table(), "in", {it.flags, video::texel_word(it)}));
  }
  void cycles(int n, bool sampler) {
    for (int i = 0; i < n; ++i) {
      unit_.cycle(sampler);
      items.push_back(channel_item(D::table(), "cycle", {sampler ? 1u : 0u}));
    }
  }
  // Cycles without the sampler until every row is written and a pending swap is done.
  void drain() {
    while (unit_.map().swap_pending() || !unit_.map().row_buffers().idle()) cycles(1, false);
  }
  const video::VideoUnit& unit() const { return unit_; }
  std::vector<Txn> items;

 private:
  video::VideoUnit unit_;
};

// Frame tags are 16 bits: frame 65 535 of a video map is tag 1 again, after 0xFFFE (golden
// frame_tag), and the row buffers compare tags as serial numbers. A 1 x 4 interlaced video:
// frames 1 .. 65 533 begin and are cut short at their first texel (each dropped by the next
// one's: the tags go round at an item a frame). Frame 65 534 (tag 0xFFFE) gets lines 0, 2 and
// 1 under a sampler that wants every cycle, L = 1000, and is dropped by frame 65 535 (tag 1),
// which goes to the same buffer: at its line 2 the reads of line 0 find that row's cells in two
// row buffers, frame 65 534's (flushed, waiting for L) and its own. The read must take frame
// 65 535's, the newer; with the tags compared as plain numbers it takes frame 65 534's, and
// frame 65 535's level 1 is wrong. So: golden's front buffer holds frame 65 535's box pyramid,
// and hls and rtl equal golden output for output, request for request (tried: an RTL comparing
// the tags as plain numbers fails).
TEST(VideoUnitTest, AVideoRunsPastTheFrameTagsWrap) {
  const video::VideoFormat f{0, 2, true, 1};
  video::VideoMapConfig config{f, 0, 1, {}};
  config.arbiter.max_wait = 4;
  config.arbiter.read_wait = 0;
  Items run(video_unit_config_item(config));
  const auto frame = [&](uint32_t k) { return video::frame_items(f, video::test_frame(f, k)); };
  for (uint32_t k = 0; k < 0xFFFD; ++k) {  // frames 1 .. 65 533: their first texel
    run.texel(frame(k).at(0));
    run.drain();
  }
  config.arbiter.max_wait = 1000;  // new bounds only: the same video map
  run.configure(video_unit_config_item(config));
  const std::vector<video::VideoItem> a = frame(0xFFFD);  // frame 65 534, tag 0xFFFE
  for (size_t i = 0; i < 3; ++i) {
    run.texel(a[i]);
    run.cycles(2, true);
  }
  const std::vector<video::VideoItem> b = frame(0xFFFE);  // frame 65 535, tag 1
  for (const video::VideoItem& it : b) {
    run.texel(it);
    run.cycles(2, true);
  }
  // Lines 0 and 2 read for both frames, each in banks 0 and 1.
  EXPECT_EQ(run.unit().map().row_buffers().stats().read_accesses, 8u);
  config.arbiter.max_wait = 4;
  run.configure(video_unit_config_item(config));
  run.drain();

  // Golden: frame 65 535 alone was shown, its box pyramid in the front buffer.
  const video::VideoUnit::Counts counts = run.unit().counts();
  EXPECT_EQ(counts.shown, 1u);
  EXPECT_EQ(counts.dropped, 0xFFFEu);
  EXPECT_EQ(counts.lost_writes, 0u);
  const video::VideoMap& map = run.unit().map();
  ASSERT_EQ(map.frames().back().tag, 0xFFFFu);
  ASSERT_EQ(map.front_tag(), 0xFFFFu);
  const texram::Pyramid8 want = texram::build_pyramid(video::test_frame(f, 0xFFFE)[0]);
  const uint32_t base = map.buffer_base(map.front_buffer());
  for (int l = 0; l < map.geometry().levels(); ++l) {
    const texram::Level8& level = want[static_cast<size_t>(l)];
    for (uint32_t y = 0; y < level.height; ++y) {
      for (uint32_t x = 0; x < level.width; ++x) {
        const texram::BankCell c = map.geometry().cell(l, x, y, 0);
        EXPECT_EQ(map.memory()[c.bank][base + c.address], level.at(x, y))
            << "level " << l << " (" << x << ", " << y << ")";
      }
    }
  }

  const VideoUnitBlock block;
  const RunResult golden = block.engine("golden")->run(run.items, RunOptions{});
  ASSERT_TRUE(golden.error.empty()) << golden.error;
  for (const std::string level : {"hls", "rtl"}) {
    const RunResult r = block.engine(level)->run(run.items, RunOptions{});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    EXPECT_TRUE(r.outputs == golden.outputs) << level;
    EXPECT_TRUE(r.requests == golden.requests) << level;
    EXPECT_EQ(r.counters, golden.counters) << level;
  }
}

}  // namespace
}  // namespace tmu::tb
