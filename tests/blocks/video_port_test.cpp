// The video port receiver's own test (the conformance suite runs golden = hls = rtl on every
// stream): docs/video.md's worked case on every level, with its counts written down.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "blocks/video_port/video_port_block.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

// A 4 x 4 frame one texel short on line 1 is detected at line 2's first item: 7 texels
// accepted, that item and the 7 after it discarded, the frame dropped; the next frame is taken
// whole.
TEST(VideoPortTest, AShortLineDropsTheFrameOnEveryLevel) {
  const texram::video::VideoFormat f{2, 2, false, 1};
  std::vector<Txn> items = {video_port_config_item(f)};
  std::vector<Txn> frame = video_port_frame(f, 1);
  frame.erase(frame.begin() + 7);  // (3, 1) missing
  items.insert(items.end(), frame.begin(), frame.end());
  frame = video_port_frame(f, 2);
  items.insert(items.end(), frame.begin(), frame.end());
  std::vector<uint64_t> accepted(7, 1);
  accepted.resize(15, 0);
  accepted.resize(31, 1);
  const VideoPortBlock block;
  testing::expect_outputs(block, items, desc::video_port::out_accepted, accepted);
  const Counters want = {{"items", 31},
                         {"frames_complete", 1},
                         {"frames_dropped", 1},
                         {"items_discarded", 8},
                         {"field_order_errors", 0}};
  for (const std::string level : {"golden", "hls", "rtl"}) {
    EXPECT_EQ(block.engine(level)->run(items, RunOptions{}).counters, want) << level;
  }
}

}  // namespace
}  // namespace tmu::tb
