#include "render/video_unit_feed.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "blocks/video_unit/video_unit_block.hpp"

namespace tmu::render {

namespace video = texram::video;

namespace {

using UnitPorts = tb::desc::video_unit;

// The unit's run replayed: its writes into the banks (an access: a row's words, one request
// each), the buffers snapshotted at each swap.
std::vector<VideoUnitFrame> replay(const video::VideoMap& layout, const tb::RunResult& run) {
  const uint32_t words = layout.config().arbiter.segment_cells / tb::kVideoUnitWordCells;
  const uint32_t cells = layout.geometry().bank_cells();
  texram::BankImage memory;
  const uint32_t end = std::max(layout.buffer_base(0), layout.buffer_base(1)) + cells + 8;
  for (auto& bank : memory) bank.assign(end, 0);
  const std::vector<tb::Txn> none;
  const std::vector<tb::Txn>& requests = run.requests.empty() ? none : run.requests[0];
  std::vector<VideoUnitFrame> frames(1);
  size_t r = 0;
  for (const tb::Txn& out : run.outputs) {
    VideoUnitFrame& f = frames.back();
    ++f.cycles;
    if (out.f[UnitPorts::out_write] != 0 || out.f[UnitPorts::out_read] != 0) {
      if (r + words > requests.size()) {
        throw std::logic_error("video unit: an access without its requests");
      }
      ++(out.f[UnitPorts::out_write] != 0 ? f.writes : f.reads);
      for (uint32_t w = 0; w < words; ++w) {
        const tb::Txn& q = requests[r++];
        if (q.f[UnitPorts::mem_req_write] == 0) continue;
        for (uint32_t i = 0; i < tb::kVideoUnitWordCells; ++i) {
          if (q.f[UnitPorts::mem_req_mask + i] == 0) continue;
          memory.at(q.f[UnitPorts::mem_req_bank]).at(q.f[UnitPorts::mem_req_addr] + i) =
              static_cast<uint8_t>(q.f[UnitPorts::mem_req_data + i]);
        }
      }
    }
    if (out.f[UnitPorts::out_swap] == 0) continue;
    auto b = std::make_shared<VideoBuffers>();
    for (int k = 0; k < 2; ++k) {
      auto t = std::make_shared<texram::TexramTexture>();
      t->kind = layout.config().format.planes == 1 ? texram::TexelKind::kLuminance
                                                   : texram::TexelKind::kTrueColour;
      t->geometry = layout.geometry();
      const uint32_t base = layout.buffer_base(k);
      for (size_t bank = 0; bank < t->banks.size(); ++bank) {
        t->banks[bank].assign(memory[bank].begin() + base, memory[bank].begin() + base + cells);
      }
      b->buffers[static_cast<size_t>(k)] = t;
    }
    b->front = static_cast<int>(out.f[UnitPorts::out_front]);
    b->shown = static_cast<int>(frames.size()) - 1;
    b->by_unit = true;
    f.buffers = b;
    frames.emplace_back();
  }
  frames.pop_back();  // the frame after the last swap: none
  return frames;
}

}  // namespace

VideoUnitFeed feed_video_unit(const host::Video& v, uint32_t base, int last, Level level,
                              std::optional<Level> check) {
  // The chip's unit: rows of a page (the configuration's default, as the golden VideoFeed's).
  video::VideoMapConfig config{video_format(v), base, 1, {}};
  const video::VideoMap layout(config);  // where the buffers are
  std::vector<std::vector<video::VideoItem>> frames;
  for (int k = 0; k <= last; ++k)
    frames.push_back(video::frame_items(config.format, video_frame(v, k)));
  tb::BlockOptions options;
  options.video_cells = config.arbiter.segment_cells;
  const auto block = std::make_shared<tb::VideoUnitBlock>(options);
  const auto unit_run = [&block] {
    UnitRun run;
    run.kind = "video_unit";
    attach(run, block);
    return run;
  };
  UnitRun run = unit_run();
  tb::VideoUnitFeedItems items = tb::video_unit_feed_items(config, frames);
  run.items = std::move(items.items);
  run_unit(run, level, {});
  VideoUnitFeed feed;
  feed.items = run.items.size();
  feed.cycles = run.result.outputs.size();
  feed.cycles_per_item = items.cycles_per_item;
  feed.frames = replay(layout, run.result);
  if (feed.frames.size() != frames.size()) {
    throw std::logic_error(
        fmt::format("video unit: {} swaps for {} frames", feed.frames.size(), frames.size()));
  }
  if (check) {  // the same items at the reference level (moved there: they are large)
    UnitRun reference = unit_run();
    reference.items = std::move(run.items);
    run_unit(reference, *check, {});
    feed.check =
        tb::compare(block->outputs(), reference.result, run.result, block->request_schemas());
    feed.check_level = engine_name(*check);
  }
  return feed;  // the runs' items and logs go: the buffers at each swap are what is kept
}

uint64_t differing_cells(const VideoBuffers& a, const VideoBuffers& b) {
  uint64_t n = a.front != b.front;
  for (size_t k = 0; k < 2; ++k) {
    for (size_t bank = 0; bank < 8; ++bank) {
      const std::vector<uint8_t>& x = a.buffers[k]->banks[bank];
      const std::vector<uint8_t>& y = b.buffers[k]->banks[bank];
      if (x.size() != y.size()) return n + std::max(x.size(), y.size());
      for (size_t i = 0; i < x.size(); ++i) n += x[i] != y[i];
    }
  }
  return n;
}

}  // namespace tmu::render
