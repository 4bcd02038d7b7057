// The video row buffers' own tests (the conformance suite runs golden = hls = rtl): a wait
// beyond 16 bits saturates (the suite's runs are far shorter), and the figure
// of docs/video.md, sampler cycles lost to a 512 x 512 video at 30 frames per second, with the
// chip's row (a 512-cell DRAM page, the golden default) against the block's short row (8
// cells, rtl/texram/tmu_video_rows.sv's default), from the golden cycle model at the block's 8
// buffers a bank.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "blocks/video_rows/video_rows_block.hpp"
#include "tests/cosim_test_support.hpp"
#include "texram/video/video_map.hpp"

namespace tmu::tb {
namespace {
namespace video = texram::video;

std::vector<video::VideoItem> two_frames(const video::VideoFormat& f) {
  std::vector<video::VideoItem> items;
  for (uint32_t k = 0; k < 2; ++k) {
    const std::vector<video::VideoItem> v = video::frame_items(f, video::test_frame(f, k));
    items.insert(items.end(), v.begin(), v.end());
  }
  return items;
}

// Two frames back to back at 512 x 512 x 30 texels a second (0.236 texels a 30 ns cycle), the
// sampler wanting every cycle, L = 64: the sampler loses exactly the accesses and their page
// faults. Rows of 512 cells (the chip's) and of 8 (the block's), 8 buffers a bank (the block's)
// and, for 8-cell rows, 32. Asserted (measured 2026-12-04; the 512-cell rows are the figures of
// tests/video_test.cpp's VideoFigureTest): the lost cycles, the lost writes (four planes
// overflow 8 buffers of 8-cell rows: the sizing of docs/video.md is for 512-cell rows), no late
// read.
TEST(VideoRowsTest, SamplerCyclesLostTo512VideoAt30fpsByRowLength) {
  const double cycles_per_second = 1e9 / static_cast<double>(video::kCycleNs);
  struct Row {
    int planes;
    bool interlaced;
    uint32_t cells;
    int buffers;           // a bank
    uint64_t lost;         // sampler cycles lost over the two frames
    uint64_t lost_writes;  // cell writes that found no free buffer
  };
  for (const Row& row : {Row{1, false, 512, 8, 2752, 0}, Row{4, false, 512, 8, 10944, 0},
                         Row{1, true, 512, 8, 4800, 0}, Row{4, true, 512, 8, 15040, 0},
                         Row{1, false, 8, 8, 174776, 0}, Row{4, false, 8, 8, 488421, 842616},
                         Row{1, true, 8, 8, 208568, 0}, Row{4, true, 8, 8, 500279, 1310480},
                         Row{1, false, 8, 32, 174776, 0}, Row{4, false, 8, 32, 699062, 0},
                         Row{1, true, 8, 32, 208568, 0}, Row{4, true, 8, 32, 805750, 0}}) {
    const video::VideoFormat f{9, 9, row.interlaced, row.planes};
    video::VideoMapConfig cfg{f, 0, 1, {}};
    cfg.arbiter = video_rows_config(64, 0);
    cfg.arbiter.segment_cells = row.cells;
    cfg.arbiter.buffers_per_bank = row.buffers;
    video::VideoMap map(cfg);
    video::RunOptions o;
    o.rate = video::video_rate(512, 512, 30);
    o.sampler = video::SamplerPattern::kFull;
    video::run(map, two_frames(f), o);
    const video::ArbiterStats& s = map.row_buffers().stats();
    const double per_second = static_cast<double>(s.sampler_lost) / 2 * 30;
    std::printf(
        "512x512 30 fps, %d plane(s)%s, rows of %u cells, %d a bank: %llu write accesses, %llu "
        "write "
        "faults, %llu reads, %llu read faults; sampler lost %llu cycles a frame, %.0f a second "
        "= %.3f %%; write wait max %llu; buffers high-water %zu a bank; lost writes %llu\n",
        row.planes, row.interlaced ? " interlaced" : " progressive", row.cells, row.buffers,
        static_cast<unsigned long long>(s.write_accesses / 2),
        static_cast<unsigned long long>(s.page_faults / 2),
        static_cast<unsigned long long>(s.read_accesses / 2),
        static_cast<unsigned long long>(s.read_faults / 2),
        static_cast<unsigned long long>(s.sampler_lost / 2), per_second,
        100.0 * per_second / cycles_per_second, static_cast<unsigned long long>(s.max_latency),
        s.max_busy_bank, static_cast<unsigned long long>(s.lost_writes));
    EXPECT_EQ(s.sampler_lost, s.write_cycles + s.read_cycles);
    EXPECT_EQ(s.lost_writes, row.lost_writes);
    EXPECT_EQ(map.late_reads(), 0u);
    EXPECT_EQ(s.sampler_lost, row.lost);
  }
}

// A row held by the swap barrier for 70 000 cycles of a sampler at every cycle, then released:
// its wait counter saturates at 0xFFFF, which is still >= L, so the row is forced in the next
// cycle with the wait 0xFFFF, alike on golden (which counts in 64 bits and clips the output),
// hls and rtl.
TEST(VideoRowsTest, WaitsSaturateAtSixteenBits) {
  using D = desc::video_rows;
  const BlockPorts& t = D::table();
  std::vector<Txn> items = {channel_item(t, "cfg", {4, 0}), channel_item(t, "hold", {0})};
  for (uint64_t c = 0; c < 8; ++c) items.push_back(channel_item(t, "put", {0, c, 10 + c, 1}));
  const size_t held = 70'000;
  for (size_t i = 0; i < held; ++i) items.push_back(channel_item(t, "cycle", {1}));
  items.push_back(channel_item(t, "hold", {0xFFFF}));
  items.push_back(channel_item(t, "cycle", {1}));
  std::vector<uint64_t> want(held, 0);
  want.push_back(0xFFFF);
  testing::expect_outputs(VideoRowsBlock(), items, D::out_wait, want);
}

// Frame tags wrap (golden frame_tag: ..., 0xFFFE, then 1) and compare as serial numbers, so the
// frame after the wrap is the newer one, alike on golden, hls and rtl. Two buffers of bank 0
// collect row 0, frame 0xFFFE's (cell 0 = 10) and then frame 1's (cell 0 = 20): a read of the
// row takes frame 1's cell; with the barrier on frame 0xFFFE, frame 0xFFFE's row is written and
// frame 1's waits until the barrier is lifted. (Compared as plain numbers, 0xFFFE would be the
// newer: the read would take 10, and frame 1's row would go at once.)
TEST(VideoRowsTest, FrameTagsWrapAndCompareAsSerialNumbers) {
  using D = desc::video_rows;
  const BlockPorts& t = D::table();
  const auto cycle = [&] { return channel_item(t, "cycle", {0}); };
  const std::vector<Txn> items = {
      channel_item(t, "cfg", {4, 0}),
      channel_item(t, "put", {0, 0, 10, 0xFFFE}),
      channel_item(t, "put", {0, 0, 20, 1}),
      channel_item(t, "read", {0, 0}),
      cycle(),  // the read, a page fault: two cycles
      cycle(),
      channel_item(t, "hold", {0xFFFE}),
      channel_item(t, "flush", {1}),
      channel_item(t, "flush", {0xFFFE}),
      cycle(),  // frame 0xFFFE's row (the page is open)
      cycle(),  // frame 1's waits
      channel_item(t, "hold", {0xFFFF}),
      cycle(),  // frame 1's row
  };
  testing::expect_outputs(VideoRowsBlock(), items, D::out_read, {1, 0, 0, 0, 0});
  testing::expect_outputs(VideoRowsBlock(), items, D::out_write, {0, 0, 1, 0, 1});
  testing::expect_outputs(VideoRowsBlock(), items, D::out_data, {20, 0, 10, 0, 20});
}

}  // namespace
}  // namespace tmu::tb
