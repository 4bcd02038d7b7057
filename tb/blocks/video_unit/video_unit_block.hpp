// The TEXRAM's video unit as a co-simulation block, `texsim cosim video_unit`: the serial video
// port, a mipmap generator per plane, the page-row buffers and the arbiter into the shared
// memory, the reads of the line above, and double buffering by a swap of the front buffer
// (000 §11-12; golden/texram/video/video_map.hpp, rtl/texram/tmu_video_unit.sv,
// hls/texram/video_unit_sc.hpp, docs/video.md).
//
// The block is VideoMap at 8-cell rows (--video-cells 512: the chip's rows of a page, rtl
// variant "page") and 8 buffers a bank, with a read queue of 64 and 16-bit frame tags. Channels
// (video_unit.json): cfg is the format (sides up to 2^9), the two buffers' bases and the
// arbiter's bounds; in takes one item of the port (no output); an item of cycle is one memory
// cycle with whether the sampler wants it, and gives one output: whether the sampler got it, the
// access that started (also requests on mem_req, one per 8-cell word of the row: writes of its
// cells, or reads of a row of the line above, whose words come back on mem_resp) and whether the
// front buffer was swapped. stat: frames shown, frames dropped, overruns, late reads, lost
// writes, forced accesses. The memory (VideoMemory) answers a read after 1 to 3 cycles.
//
// The stimulus: runs of frames of a format (1 x 1 to 64 x 64, progressive and interlaced, one
// and four planes; interlaced lines of at most 64 bytes, whose reads fit the queue) with the
// memory cycles between items at a rate and a sampler load drawn per frame (idle to every
// cycle), now and then a malformed frame (a texel missing, a frame cut short) or frames faster
// than their swaps (overruns); each run drained (every row written, the last swap done) before
// the next configuration.
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/video_unit/video_unit_ports.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "texram/video/video_map.hpp"

TMU_DESCRIBE(video_unit)

namespace tmu::tb {

// The memory port's word: the cells of a request's data (video_unit.json), a row's access being
// its cells / this many requests.
inline constexpr uint32_t kVideoUnitWordCells =
    desc::video_unit::mem_req_data_end_ - desc::video_unit::mem_req_data_slot_ + 1;

// The cells of the unit's row buffers: the block's (rtl variant "") and a page's, the chip's
// (rtl variant "page", BlockOptions::video_cells).
inline constexpr uint32_t kVideoUnitCells = 8;
inline constexpr uint32_t kVideoUnitPageCells = 512;

// The unit's VideoMap for a configuration item (rows of `cells`, 8 buffers a bank), and its
// limits.
texram::video::VideoMapConfig video_unit_config(const Txn& cfg, uint32_t cells = kVideoUnitCells);
inline constexpr size_t kVideoUnitReadQueue = 64;
inline constexpr int kVideoUnitMaxLog2 = 9;

// The configuration item of a video map (the rows are the block's option, not an item's).
Txn video_unit_config_item(const texram::video::VideoMapConfig& config);
// What a render feeds the unit (render/video_unit_feed) at rows of config.arbiter.segment_cells
// (8 or 512): the configuration item of `config`, then each frame's port items, each followed by
// the same number of memory cycles, and cycles after the frame until it is swapped in and every row
// buffer is written; the sampler leaves every cycle to the unit (the render's pixel pass runs
// between two frames' feeds). The rate is the fastest of one texel in 1, 2, 4, ... 16 cycles at
// which every frame is shown whole (with 8-cell rows an interlaced four-plane line's reads of the
// line above hold the writes back while the port goes on, and at the full rate 8 row buffers a
// bank overflow; at a page one a cycle serves). Throws std::runtime_error when no such rate
// exists, or the read queue overflows (an interlaced line wider than the unit reads).
struct VideoUnitFeedItems {
  std::vector<Txn> items;
  int cycles_per_item = 1;
};
VideoUnitFeedItems video_unit_feed_items(
    const texram::video::VideoMapConfig& config,
    const std::vector<std::vector<texram::video::VideoItem>>& frames);

class VideoUnitBlock : public DescribedBlockOf<VideoUnitBlock> {
 public:
  explicit VideoUnitBlock(const BlockOptions& options = {});
  std::vector<Txn> setup_items() const override;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;
  std::string variant() const override;
  std::string repro_options() const override;
  TMU_BLOCK_PIECES;

 private:
  std::vector<Txn> workload_items() const;

  BlockOptions options_;
  // cover() sees the items in order: the golden unit over them.
  struct CoverState;
  mutable std::shared_ptr<CoverState> cover_;
};

}  // namespace tmu::tb
