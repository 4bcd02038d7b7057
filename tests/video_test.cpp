// Video mapping (000 §11-12; docs/video.md): the video port's stream and its receiver's checks,
// the frames in memory against build_pyramid, the page-row buffers and the arbiter's counts,
// double buffering read by a sampler, and the figure of the sampler cycles a video costs.
#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>
#include <random>
#include <set>
#include <utility>

#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"
#include "texram/video/video_map.hpp"
#include "texram/video/video_unit.hpp"

namespace tmu::texram::video {
namespace {

// Frames first .. first + n - 1 of test_frame, back to back.
std::vector<VideoItem> stream_of(const VideoFormat& f, uint32_t first, uint32_t n) {
  std::vector<VideoItem> items;
  for (uint32_t k = first; k < first + n; ++k) {
    const std::vector<VideoItem> v = frame_items(f, test_frame(f, k));
    items.insert(items.end(), v.begin(), v.end());
  }
  return items;
}

// Every plane's pyramid of test frame k.
std::vector<Pyramid8> pyramids_of(const VideoFormat& f, uint32_t k) {
  std::vector<Pyramid8> p;
  for (const Level8& plane : test_frame(f, k)) p.push_back(build_pyramid(plane));
  return p;
}

std::vector<uint8_t> flags_of(const std::vector<VideoItem>& items) {
  std::vector<uint8_t> f;
  for (const VideoItem& i : items) f.push_back(i.flags);
  return f;
}

// ---- the port -----------------------------------------------------------------------------

TEST(VideoPortTest, ItemsCarryTheFlagsOfTheirPlace) {
  // 2 x 4 interlaced: (0,0) (1,0) (0,2) (1,2) | (0,1) (1,1) (0,3) (1,3). First of frame, field,
  // line = 1, 2, 4; field 2 = 8.
  const VideoFormat il{1, 2, true, 1};
  const std::vector<VideoItem> items = frame_items(il, test_frame(il, 0));
  EXPECT_EQ(flags_of(items), (std::vector<uint8_t>{7, 0, 4, 0, 14, 8, 12, 8}));
  EXPECT_EQ(items[2].bytes[0], test_frame(il, 0)[0].at(0, 2));
  EXPECT_EQ(items[4].bytes[0], test_frame(il, 0)[0].at(0, 1));
  // Progressive 2 x 2, and a one-line interlaced frame (one field: progressive).
  EXPECT_EQ(flags_of(frame_items({1, 1, false, 1}, test_frame({1, 1, false, 1}, 0))),
            (std::vector<uint8_t>{7, 0, 4, 0}));
  EXPECT_EQ(flags_of(frame_items({2, 0, true, 1}, test_frame({2, 0, true, 1}, 0))),
            (std::vector<uint8_t>{7, 0, 0, 0}));
  // Four planes: plane p's byte in bytes[p].
  const VideoFormat rgba{1, 1, false, 4};
  const VideoFrame fr = test_frame(rgba, 3);
  const std::vector<VideoItem> four = frame_items(rgba, fr);
  for (size_t p = 0; p < 4; ++p) EXPECT_EQ(four[3].bytes[p], fr[p].at(1, 1));
  EXPECT_THROW(frame_items(rgba, test_frame(il, 0)), std::invalid_argument);
}

TEST(VideoPortTest, TestFramesDifferFromFrameToFrameAndPlaneToPlane) {
  const VideoFormat f{6, 6, false, 4};
  const VideoFrame a = test_frame(f, 0), b = test_frame(f, 1);
  for (size_t p = 0; p < 4; ++p) {
    size_t same = 0, same_plane = 0;
    for (size_t i = 0; i < a[p].texels.size(); ++i) {
      same += a[p].texels[i] == b[p].texels[i];
      same_plane += a[p].texels[i] == a[(p + 1) % 4].texels[i];
    }
    EXPECT_LT(same, a[p].texels.size() / 16);  // the ramp moves by 7 and the noise changes
    EXPECT_LT(same_plane, a[p].texels.size() / 16);
  }
}

TEST(VideoPortTest, ReceiverTakesFramesBackToBackInSourceOrder) {
  const VideoFormat f{2, 2, true, 1};
  VideoReceiver rx(f);
  const std::vector<VideoItem> items = stream_of(f, 0, 3);
  const auto order = source_order(f);
  for (size_t i = 0; i < items.size(); ++i) {
    const Received r = rx.step(items[i]);
    ASSERT_TRUE(r.accepted) << i;
    EXPECT_EQ(r.x, order[i % 16][0]);
    EXPECT_EQ(r.y, order[i % 16][1]);
    EXPECT_EQ(r.frame_start, i % 16 == 0);
    EXPECT_EQ(r.frame_end, i % 16 == 15);
  }
  EXPECT_EQ(rx.stats(), (ReceiverStats{48, 3, 0, 0, 0}));
}

TEST(VideoPortTest, AShortLineDropsTheFrameAndTheNextFrameIsTaken) {
  const VideoFormat f{2, 2, false, 1};
  std::vector<VideoItem> items = stream_of(f, 0, 2);
  items.erase(items.begin() + 5);  // line 1 one texel short
  VideoReceiver rx(f);
  std::vector<Received> r;
  for (const VideoItem& i : items) r.push_back(rx.step(i));
  // Items 0-6 accepted (line 1's last texel where (2, 1) was due: the flags agree); item 7,
  // line 2's start where (3, 1) was due, drops the frame and is discarded, as are the 7 after
  // it; frame 1 (items 15..30) is taken whole.
  for (size_t i = 0; i < 7; ++i) EXPECT_TRUE(r[i].accepted) << i;
  EXPECT_TRUE(r[7].dropped);
  EXPECT_EQ(r[7].error, VideoError::kBadFlags);
  EXPECT_FALSE(r[7].accepted);
  EXPECT_TRUE(r[15].accepted && r[15].frame_start);
  EXPECT_EQ(rx.stats(), (ReceiverStats{31, 1, 1, 8, 0}));
}

TEST(VideoPortTest, ALongLineDropsTheFrame) {
  const VideoFormat f{2, 2, false, 1};
  std::vector<VideoItem> items = stream_of(f, 0, 2);
  items.insert(items.begin() + 4, VideoItem{0, {}});  // line 0 one texel long
  VideoReceiver rx(f);
  for (const VideoItem& i : items) rx.step(i);
  // The extra item arrives where (0, 1) must carry first of line: dropped; it and lines 1-3
  // (12 items) are discarded.
  EXPECT_EQ(rx.stats(), (ReceiverStats{33, 1, 1, 13, 0}));
}

TEST(VideoPortTest, AFrameCutShortLosesOnlyItself) {
  const VideoFormat f{2, 2, true, 1};
  std::vector<VideoItem> items = stream_of(f, 0, 1);
  items.resize(10);
  const std::vector<VideoItem> next = stream_of(f, 1, 1);
  items.insert(items.end(), next.begin(), next.end());
  VideoReceiver rx(f);
  Received at_cut;
  for (size_t i = 0; i < items.size(); ++i) {
    const Received r = rx.step(items[i]);
    if (i == 10) at_cut = r;
  }
  EXPECT_TRUE(at_cut.dropped && at_cut.accepted && at_cut.frame_start);
  EXPECT_EQ(rx.stats(), (ReceiverStats{26, 1, 1, 0, 0}));
}

TEST(VideoPortTest, FieldTwoBeforeFieldOneIsDiscarded) {
  // A source that sends field 2 first, its first item flagged first of frame: an error; the
  // receiver waits for a first-of-frame item of field 1, so the whole frame is lost; the next
  // well-ordered frame is taken.
  const VideoFormat f{2, 2, true, 1};
  const std::vector<VideoItem> good = stream_of(f, 0, 1);
  std::vector<VideoItem> items(good.begin() + 8, good.end());  // field 2
  items.insert(items.end(), good.begin(), good.begin() + 8);   // field 1
  items[0].flags |= kFrameStart;
  items[8].flags &= static_cast<uint8_t>(~kFrameStart);
  const std::vector<VideoItem> next = stream_of(f, 1, 1);
  items.insert(items.end(), next.begin(), next.end());
  VideoReceiver rx(f);
  const Received first = rx.step(items[0]);
  EXPECT_EQ(first.error, VideoError::kFieldOrder);
  for (size_t i = 1; i < items.size(); ++i) rx.step(items[i]);
  EXPECT_EQ(rx.stats(), (ReceiverStats{32, 1, 0, 16, 1}));
}

// ---- video mapping ------------------------------------------------------------------------

// Runs `items` through a map of `cfg`; at every swap checks the front buffer against the
// pyramids of test frame `frame_of(tag)` and the DRF base against the front buffer; returns the
// front buffer's cells at each swap, by tag.
struct SwapCheck {
  std::vector<std::pair<uint64_t, BankImage>> fronts;
  size_t swaps = 0;
};
SwapCheck run_and_check(const VideoMapConfig& cfg, const std::vector<VideoItem>& items,
                        const RunOptions& base_options, uint32_t first_frame,
                        const std::vector<uint32_t>& frame_of_tag = {}) {
  SwapCheck out;
  VideoMap map(cfg);
  RunOptions o = base_options;
  uint64_t seen = 0;
  o.on_cycle = [&](const VideoMap& m, bool) {
    if (m.front_tag() == seen) return;
    seen = m.front_tag();
    ++out.swaps;
    const uint32_t k = frame_of_tag.empty() ? first_frame + static_cast<uint32_t>(seen) - 1
                                            : frame_of_tag[seen - 1];
    const std::vector<Pyramid8> expect = pyramids_of(cfg.format, k);
    EXPECT_EQ(m.drfs()[static_cast<size_t>(cfg.drf - 1)].base, m.buffer_base(m.front_buffer()));
    for (int p = 0; p < cfg.format.planes; ++p) {
      EXPECT_EQ(m.read_pyramid(m.front_buffer(), p), expect[static_cast<size_t>(p)])
          << "tag " << seen << " plane " << p;
    }
    BankImage front;
    for (size_t b = 0; b < 8; ++b) {
      const auto first = m.memory()[b].begin() + m.buffer_base(m.front_buffer());
      front[b].assign(first, first + m.geometry().bank_cells());
    }
    out.fronts.emplace_back(seen, std::move(front));
  };
  run(map, items, o);
  EXPECT_EQ(map.row_buffers().stats().lost_writes, 0u);
  EXPECT_EQ(map.late_reads(), 0u);
  return out;
}

// The buffered map against the direct (unbuffered) one: the same frames, the same cells.
void expect_frames_in_memory(const VideoFormat& f, uint32_t frames, const RunOptions& o) {
  SCOPED_TRACE(::testing::Message()
               << f.width() << " x " << f.height() << (f.interlaced ? " interlaced" : "")
               << " planes " << f.planes);
  const std::vector<VideoItem> items = stream_of(f, 0, frames);
  VideoMapConfig cfg{f, 1000, 3, {}};
  const SwapCheck buffered = run_and_check(cfg, items, o, 0);
  cfg.arbiter.direct = true;
  const SwapCheck direct = run_and_check(cfg, items, o, 0);
  EXPECT_EQ(buffered.swaps, frames);
  ASSERT_EQ(buffered.fronts.size(), direct.fronts.size());
  for (size_t i = 0; i < direct.fronts.size(); ++i) {
    EXPECT_EQ(buffered.fronts[i].first, direct.fronts[i].first);
    EXPECT_TRUE(buffered.fronts[i].second == direct.fronts[i].second) << "frame " << i;
  }
}

RunOptions random_sampler(VideoRate rate, uint64_t seed) {
  RunOptions o;
  o.rate = rate;
  o.sampler = SamplerPattern::kRandom;
  o.random_percent = 50;
  o.seed = seed;
  std::cout << "sampler seed " << seed << "\n";
  return o;
}

TEST(VideoMapTest, EveryFrameInMemoryIsItsPyramidProgressiveAndInterlaced) {
  for (bool interlaced : {false, true}) {
    expect_frames_in_memory({6, 5, interlaced, 1}, 5, random_sampler({1, 4}, 11));
    expect_frames_in_memory({5, 6, interlaced, 1}, 3, random_sampler({1, 2}, 12));
  }
}

// Tiny frames at rates that give each at least 256 cycles: a frame must outlast the swap of the
// one before it (L plus two cycles per buffer ready; docs/video.md).
TEST(VideoMapTest, OneLineAndOneColumnFrames) {
  for (bool interlaced : {false, true}) {
    expect_frames_in_memory({4, 0, interlaced, 1}, 4, random_sampler({1, 16}, 21));
    expect_frames_in_memory({0, 4, interlaced, 1}, 4, random_sampler({1, 16}, 22));
    expect_frames_in_memory({0, 0, interlaced, 1}, 4, random_sampler({1, 256}, 23));
    expect_frames_in_memory({0, 1, interlaced, 4}, 3, random_sampler({1, 128}, 24));
  }
}

// A frame complete before the one before it could be swapped in (the swap waits for its last
// buffers): the model refuses, naming both frames.
// 1 x 1 frames at one texel in three cycles under a full sampler: each frame is complete long
// before the previous one's swap (L + 2 cycles), so every second frame is an overrun, never
// shown, and the one after it goes to the same buffer.
TEST(VideoMapTest, AFrameCompleteBeforeTheSwapIsAnOverrun) {
  const VideoFormat f{0, 0, false, 1};
  VideoMap map({f, 0, 1, {}});
  RunOptions o;
  o.rate = {1, 3};
  o.sampler = SamplerPattern::kFull;
  run(map, stream_of(f, 0, 6), o);
  ASSERT_EQ(map.frames().size(), 6u);
  EXPECT_GT(map.overruns(), 0u);
  uint64_t shown = 0;
  for (const FrameRecord& r : map.frames()) {
    EXPECT_NE(r.complete, r.dropped) << "frame " << r.tag;
    EXPECT_EQ(r.swap_cycle.has_value(), r.complete) << "frame " << r.tag;
    shown += r.complete;
  }
  EXPECT_EQ(shown + map.overruns(), 6u);
  EXPECT_EQ(map.front_tag(), map.frames()[map.front_tag() - 1].tag);
  EXPECT_EQ(map.read_pyramid(map.front_buffer(), 0)[0].at(0, 0),
            test_frame(f, static_cast<uint32_t>(map.front_tag() - 1))[0].at(0, 0));
}

TEST(VideoMapTest, FourPlaneVideo) {
  expect_frames_in_memory({6, 6, true, 4}, 3, random_sampler({1, 4}, 31));
  expect_frames_in_memory({7, 3, false, 4}, 3, random_sampler({1, 1}, 32));
}

// A texel per cycle and no blanking: the fastest source the port takes (more than one texel a
// cycle is allowed too: the model takes several items in one cycle).
TEST(VideoMapTest, FramesBackToBackWithoutBlanking) {
  RunOptions o = random_sampler({3, 2}, 41);
  o.sampler = SamplerPattern::kFull;
  expect_frames_in_memory({5, 5, true, 1}, 6, o);
  expect_frames_in_memory({5, 5, false, 4}, 4, o);
}

// The write accesses a frame needs: one per (bank, segment) its cells touch (a segment's buffer
// is written once, when full or at the frame's end), counted from mipgen_frame's writes.
uint64_t expected_write_accesses(const VideoMap& map, uint32_t frames) {
  const VideoFormat& f = map.config().format;
  uint64_t n = 0;
  for (uint32_t k = 0; k < frames; ++k) {
    const uint32_t base = map.buffer_base(static_cast<int>(1 - k % 2));  // frame 1 to buffer 1
    std::set<std::pair<unsigned, uint32_t>> segments;
    const VideoFrame fr = test_frame(f, k);
    for (int p = 0; p < f.planes; ++p) {
      for (const CellWrite& w : mipgen_frame({f.log2_w, f.log2_h, f.interlaced, f.planes, p},
                                             fr[static_cast<size_t>(p)])) {
        segments.insert(
            {w.cell.bank, (base + w.cell.address) / map.config().arbiter.segment_cells});
      }
    }
    n += segments.size();
  }
  return n;
}

// The reads an interlaced frame needs: for each field-2 line y, one per (bank, segment) the
// cells of line y - 1 occupy (a two-line frame takes its line 0 as it arrives: none).
uint64_t expected_read_accesses(const VideoMap& map, uint32_t frames) {
  const VideoFormat& f = map.config().format;
  if (!f.fields() || f.height() == 2) return 0;
  uint64_t n = 0;
  for (uint32_t k = 0; k < frames; ++k) {
    const uint32_t base = map.buffer_base(static_cast<int>(1 - k % 2));
    for (uint32_t y = 1; y < f.height(); y += 2) {
      std::set<std::pair<unsigned, uint32_t>> segments;
      for (uint32_t x = 0; x < map.geometry().stored_width(0); ++x) {
        for (int p = 0; p < f.planes; ++p) {
          const BankCell c = map.geometry().cell(0, x, y - 1, p);
          segments.insert({c.bank, (base + c.address) / map.config().arbiter.segment_cells});
        }
      }
      n += segments.size();
    }
  }
  return n;
}

TEST(VideoArbiterTest, SamplerAtFullRateLosesExactlyTheWriteCycles) {
  for (const VideoFormat f : {VideoFormat{7, 7, false, 1}, VideoFormat{7, 7, true, 4}}) {
    VideoMapConfig cfg{f, 0, 1, {}};
    VideoMap map(cfg);
    RunOptions o;
    o.rate = video_rate(512, 512, 30);
    o.sampler = SamplerPattern::kFull;
    run(map, stream_of(f, 0, 3), o);
    const ArbiterStats& s = map.row_buffers().stats();
    EXPECT_EQ(s.write_accesses, expected_write_accesses(map, 3));
    // Every write and read took the sampler's cycles: its access and its page fault's.
    EXPECT_EQ(s.sampler_lost, s.write_cycles + s.read_cycles);
    EXPECT_EQ(s.write_cycles, s.write_accesses + s.page_faults);
    EXPECT_EQ(s.read_cycles, s.read_accesses + s.read_faults);
    EXPECT_EQ(s.sampler_lost, s.sampler_wanted - s.sampler_granted);
    EXPECT_EQ(s.forced_writes, s.write_accesses + s.read_accesses);
    // Interlaced: the line above of each of the h / 2 field-2 lines, planes x w / 2 cells in each
    // of two banks, one segment each (at most 512 cells, aligned).
    EXPECT_EQ(s.read_accesses, expected_read_accesses(map, 3));
    EXPECT_EQ(map.late_reads(), 0u);
    // Each write waited the bound L, and those made ready together (a frame's end) also the
    // two cycles of each one before it.
    EXPECT_EQ(s.min_latency, cfg.arbiter.max_wait);
    EXPECT_LE(s.max_latency, cfg.arbiter.max_wait + 2 * (s.max_ready - 1));
    EXPECT_EQ(s.cells_written, s.cells_in);
    EXPECT_EQ(s.lost_writes, 0u);
    EXPECT_EQ(map.front_tag(), 3u);
    for (int p = 0; p < f.planes; ++p) {
      EXPECT_EQ(map.read_pyramid(map.front_buffer(), p), pyramids_of(f, 2)[static_cast<size_t>(p)]);
    }
  }
}

TEST(VideoArbiterTest, IdleSamplerLosesNothingAndWritesAtOnce) {
  const VideoFormat f{7, 7, true, 1};
  VideoMap map({f, 0, 1, {}});
  RunOptions o;
  o.rate = video_rate(512, 512, 30);
  o.sampler = SamplerPattern::kNone;
  run(map, stream_of(f, 0, 2), o);
  const ArbiterStats& s = map.row_buffers().stats();
  EXPECT_EQ(s.sampler_lost, 0u);
  EXPECT_EQ(s.forced_writes, 0u);
  EXPECT_EQ(s.write_accesses, expected_write_accesses(map, 2));
  // A buffer waits only for the buffers made ready before it (two cycles each at most).
  EXPECT_LE(s.max_latency, 2 * (s.max_ready - 1));
}

// Segments smaller than a page: a page is written in several accesses; consecutive writes of one
// page do not fault unless the sampler came between them (its access moves every bank's page).
TEST(VideoArbiterTest, SegmentsOfAPageFaultOnlyAfterTheSampler) {
  const VideoFormat f{8, 8, false, 1};
  for (SamplerPattern pattern : {SamplerPattern::kFull, SamplerPattern::kNone}) {
    VideoMapConfig cfg{f, 0, 1, {}};
    cfg.arbiter.segment_cells = 64;
    VideoMap map(cfg);
    RunOptions o;
    o.rate = video_rate(512, 512, 30);
    o.sampler = pattern;
    run(map, stream_of(f, 0, 2), o);
    const ArbiterStats& s = map.row_buffers().stats();
    EXPECT_EQ(s.write_accesses, expected_write_accesses(map, 2));
    if (pattern == SamplerPattern::kFull) {
      // Every write after a sampler access faults; only writes made ready together (a frame's
      // end) can follow one another without a sampler access between.
      EXPECT_GE(s.page_faults, s.write_accesses - s.max_ready);
      EXPECT_EQ(s.sampler_lost, s.write_accesses + s.page_faults);
    } else {
      // Level 0 of a 256-wide frame fills a bank's page in 4 of its lines, 8 segments of 64
      // written one after the other; the other levels' writes come between them.
      EXPECT_LT(s.page_faults, s.write_accesses / 2);
      EXPECT_EQ(s.sampler_lost, 0u);
    }
    EXPECT_EQ(map.read_pyramid(map.front_buffer(), 0), pyramids_of(f, 1)[0]);
  }
}

// Buffer sizing: no cell write finds its bank's buffers all busy, at every shape and mode, one
// and four planes, at the rate of a 1024 x 1024 video at 30 frames per second (0.94 texels a
// cycle), sampler at full rate. The high-water marks measured (2026-12-03) are at most 6 of the
// 8 buffers of a bank with four planes, 5 with one.
TEST(VideoArbiterTest, NoWriteIsLostAtTheStatedRates) {
  const std::vector<std::pair<int, int>> shapes{{9, 9},  {10, 10}, {10, 0}, {0, 10},
                                                {10, 1}, {6, 6},   {10, 9}};
  for (const auto& [lw, lh] : shapes) {
    for (int planes : {1, 4}) {
      if (lw + lh == 20 && planes == 4) continue;  // two buffers do not fit the chip
      for (bool interlaced : {false, true}) {
        // An interlaced line narrower than 16 texels at this rate needs more reads of the line
        // above than the memory has cycles (two a line, a line a cycle at one texel wide).
        if (interlaced && lw < 4 && lh > 1) continue;
        const VideoFormat f{lw, lh, interlaced, planes};
        VideoMap map({f, 0, 1, {}});
        RunOptions o;
        o.rate = video_rate(1024, 1024, 30);
        o.sampler = SamplerPattern::kFull;
        run(map, stream_of(f, 0, 2), o);
        const ArbiterStats& s = map.row_buffers().stats();
        EXPECT_EQ(s.lost_writes, 0u) << lw << "x" << lh << " planes " << planes;
        EXPECT_LE(s.max_busy_bank, planes == 1 ? 5u : 6u) << lw << "x" << lh << " " << planes;
        EXPECT_EQ(map.front_tag(), 2u);
        EXPECT_EQ(map.late_reads(), 0u);
      }
    }
  }
  // Four planes of 1024 x 1024 are 1.1 M cells a bank: two do not fit the 2 M of the chip.
  EXPECT_THROW(VideoMap({{10, 10, false, 4}, 0, 1, {}}), std::invalid_argument);
}

TEST(VideoArbiterTest, TooFewBuffersLoseWritesAndTheTestSeesIt) {
  // One buffer a bank cannot hold level 0's and level 2's segments at once.
  const VideoFormat f{6, 6, false, 1};
  VideoMapConfig cfg{f, 0, 1, {}};
  cfg.arbiter.buffers_per_bank = 1;
  VideoMap map(cfg);
  RunOptions o;
  o.rate = {1, 4};
  o.sampler = SamplerPattern::kFull;
  run(map, stream_of(f, 0, 1), o);
  EXPECT_GT(map.row_buffers().stats().lost_writes, 0u);
  EXPECT_NE(map.read_pyramid(map.front_buffer(), 0), pyramids_of(f, 0)[0]);
}

// ---- double buffering ---------------------------------------------------------------------

// A sampler reading the map through its DRF while frames stream in: every texel it reads is the
// texel of the frame the front buffer holds, a complete frame, never a mix; while frame k is
// received the front holds frame k - 1 (or k - 2 until k - 1's swap, shortly after k starts).
TEST(VideoDoubleBufferTest, SamplerOnlyEverReadsCompleteFrames) {
  for (bool interlaced : {false, true}) {
    const VideoFormat f{6, 6, interlaced, 1};
    const uint32_t frames = 6;
    std::vector<Pyramid8> expect;
    for (uint32_t k = 0; k < frames; ++k) expect.push_back(pyramids_of(f, k)[0]);
    VideoMapConfig cfg{f, 4096, 2, {}};
    VideoMap map(cfg);
    const Geometry& g = map.geometry();
    RunOptions o = random_sampler({1, 4}, 51 + interlaced);
    std::mt19937_64 rng(61);
    uint64_t reads = 0, mismatches = 0, early = 0;
    std::vector<uint64_t> reads_during(frames + 1, 0);
    o.on_cycle = [&](const VideoMap& m, bool granted) {
      if (!granted) return;
      const uint32_t base = m.drfs()[1].base;  // DRF 2: what the sampler reads
      const int buffer = static_cast<int>((base - cfg.base) / VideoMap::buffer_stride(g));
      const int level = static_cast<int>(rng() % static_cast<uint64_t>(g.levels()));
      const uint32_t x = static_cast<uint32_t>(rng() % g.texel_width(level));
      const uint32_t y = static_cast<uint32_t>(rng() % g.texel_height(level));
      const uint8_t got = m.read(buffer, level, x, y, 0);
      const uint64_t tag = m.front_tag();
      const uint8_t want = tag == 0 ? 0 : expect[tag - 1][static_cast<size_t>(level)].at(x, y);
      ++reads;
      mismatches += got != want;
      // The frame being received (or the last one, between frames).
      const uint64_t receiving = m.frames().empty() ? 0 : m.frames().back().tag;
      early += tag + 2 < receiving || tag > receiving;
      ++reads_during[receiving];
    };
    run(map, stream_of(f, 0, frames), o);
    EXPECT_EQ(mismatches, 0u) << "of " << reads;
    EXPECT_EQ(early, 0u);
    for (uint32_t k = 1; k <= frames; ++k) EXPECT_GT(reads_during[k], 500u) << k;
    ASSERT_EQ(map.frames().size(), frames);
    for (const FrameRecord& r : map.frames()) {
      EXPECT_EQ(r.buffer, static_cast<int>(r.tag % 2));  // 1, 0, 1, 0, ...
      ASSERT_TRUE(r.swap_cycle.has_value());
      // Swapped once its last cells are written: at most L + 2 per buffer ready at once.
      EXPECT_LE(*r.swap_cycle - r.end_cycle, 64u + 2 * 24u) << r.tag;
    }
    EXPECT_EQ(map.front_tag(), frames);
  }
}

// A malformed frame (a short line) is dropped and never shown; the next frame goes to the same
// buffer and is shown complete.
TEST(VideoDoubleBufferTest, AMalformedFrameIsNeverShown) {
  const VideoFormat f{5, 5, true, 1};
  std::vector<VideoItem> items = stream_of(f, 0, 4);
  items.erase(items.begin() + 32 * 32 + 200);  // frame 1, field 1, line 12 short by one
  VideoMapConfig cfg{f, 0, 1, {}};
  const SwapCheck c = run_and_check(cfg, items, random_sampler({1, 4}, 71), 0, {0, 1, 2, 3});
  // Tags: 1 frame 0, 2 frame 1 (dropped), 3 frame 2, 4 frame 3: shown 1, 3, 4.
  ASSERT_EQ(c.fronts.size(), 3u);
  EXPECT_EQ(c.fronts[0].first, 1u);
  EXPECT_EQ(c.fronts[1].first, 3u);
  EXPECT_EQ(c.fronts[2].first, 4u);
  VideoMap map(cfg);
  run(map, items, random_sampler({1, 4}, 71));
  ASSERT_EQ(map.frames().size(), 4u);
  EXPECT_TRUE(map.frames()[1].dropped);
  EXPECT_FALSE(map.frames()[1].swap_cycle.has_value());
  EXPECT_EQ(map.frames()[1].buffer, map.frames()[2].buffer);  // the back buffer again
  EXPECT_EQ(map.receiver().stats().frames_dropped, 1u);
  EXPECT_EQ(map.receiver().stats().frames_complete, 3u);
}

// ---- the figure ---------------------------------------------------------------------------

// Sampler cycles lost to a 512 x 512 video at 30 frames per second (one access per 30 ns, the
// sampler at full rate, L = 64, two progressive frames), one plane and four, with page-row
// buffers of 512 cells (the default) and of smaller segments: printed for docs/video.md and
// asserted (measured 2026-12-03). Also printed: the accesses a second the same video would take
// written cell by cell (no buffers), the patent's 4/3 cells per texel per plane.
TEST(VideoFigureTest, SamplerCyclesLostTo512VideoAt30fps) {
  const double cycles_per_second = 1e9 / static_cast<double>(kCycleNs);
  struct Row {
    int planes;
    uint32_t segment;
    bool interlaced;
    uint64_t lost;  // over the two frames
  };
  for (const Row& row :
       {Row{1, 512, false, 2752}, Row{4, 512, false, 10944}, Row{1, 128, false, 10942},
        Row{4, 128, false, 43710}, Row{1, 512, true, 4800}, Row{4, 512, true, 15040}}) {
    const VideoFormat f{9, 9, row.interlaced, row.planes};
    VideoMapConfig cfg{f, 0, 1, {}};
    cfg.arbiter.segment_cells = row.segment;
    VideoMap map(cfg);
    RunOptions o;
    o.rate = video_rate(512, 512, 30);
    o.sampler = SamplerPattern::kFull;
    const uint32_t frames = 2;
    const uint64_t cycles = run(map, stream_of(f, 0, frames), o);
    const ArbiterStats& s = map.row_buffers().stats();
    const double lost_per_frame = static_cast<double>(s.sampler_lost) / frames;
    const double per_second = lost_per_frame * 30;
    const double cells_per_second = static_cast<double>(s.cells_in) / frames * 30;
    std::printf(
        "512x512 30 fps, %d plane(s), segment %u%s: %llu cycles, %llu write accesses (%llu "
        "cells), %llu page faults; %llu reads, %llu read faults, read latency max %llu; sampler "
        "lost %.0f cycles a frame, %.0f a second = %.3f %% of %.0f; write latency min %llu max "
        "%llu mean %.1f; buffers high-water %zu a bank, %zu in all; cell by cell: %.0f accesses "
        "a second = %.1f %%\n",
        row.planes, row.segment, row.interlaced ? " interlaced" : "",
        static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(s.write_accesses),
        static_cast<unsigned long long>(s.cells_written),
        static_cast<unsigned long long>(s.page_faults),
        static_cast<unsigned long long>(s.read_accesses),
        static_cast<unsigned long long>(s.read_faults),
        static_cast<unsigned long long>(s.max_read_latency), lost_per_frame, per_second,
        100.0 * per_second / cycles_per_second, cycles_per_second,
        static_cast<unsigned long long>(s.min_latency),
        static_cast<unsigned long long>(s.max_latency), s.mean_latency(), s.max_busy_bank,
        s.max_busy_total, cells_per_second, 100.0 * cells_per_second / cycles_per_second);
    EXPECT_EQ(s.write_accesses, expected_write_accesses(map, frames));
    EXPECT_EQ(s.read_accesses, expected_read_accesses(map, frames));
    EXPECT_EQ(map.late_reads(), 0u);
    EXPECT_EQ(s.sampler_lost, row.lost);
    EXPECT_EQ(s.lost_writes, 0u);
  }
}

// The unit around the maps: a configuration with a new format or base starts a new map (front
// buffer 0 again), one with new bounds only keeps it; the counters run on across maps; a new map
// in the middle of a frame is refused.
TEST(VideoUnitTest, ANewMapStartsAfreshAndTheCountersRunOn) {
  const VideoFormat f{2, 2, false, 1};
  VideoUnit unit;
  unit.configure({f, 0, 1, {}});
  RunOptions o;
  o.rate = {1, 1};
  o.sampler = SamplerPattern::kNone;
  const std::vector<VideoItem> one = stream_of(f, 0, 1);
  for (const VideoItem& it : one) {
    unit.receive(it);
    unit.cycle(false);
  }
  while (unit.map().swap_pending() || !unit.map().row_buffers().idle()) unit.cycle(false);
  EXPECT_EQ(unit.counts().shown, 1u);
  EXPECT_EQ(unit.map().front_buffer(), 1);
  const VideoMap* first = &unit.map();
  VideoMapConfig bounds{f, 0, 1, {}};
  bounds.arbiter.max_wait = 3;
  unit.configure(bounds);  // the same map
  EXPECT_EQ(&unit.map(), first);
  EXPECT_EQ(unit.map().config().arbiter.max_wait, 3u);
  unit.configure({f, 512, 1, {}});  // a new base: a new map, front buffer 0, counts kept
  EXPECT_NE(&unit.map(), first);
  EXPECT_EQ(unit.map().front_buffer(), 0);
  EXPECT_EQ(unit.counts().shown, 1u);
  unit.receive(one.front());  // a frame under way
  EXPECT_THROW(unit.configure({f, 0, 1, {}}), std::logic_error);
  VideoMapConfig moved_bounds{f, 512, 1, {}};
  moved_bounds.arbiter.max_wait = 5;
  unit.configure(moved_bounds);  // new bounds only: allowed mid-frame
  EXPECT_EQ(unit.map().config().arbiter.max_wait, 5u);
}

}  // namespace
}  // namespace tmu::texram::video
