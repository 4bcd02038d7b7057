// The TEXRAM video path's page-row buffers and write arbiter as a co-simulation block,
// `texsim cosim video_rows`: the mipmap generator's cell writes are collected per bank into
// row buffers and written to the memory one buffer an access, in the cycles the sampler leaves,
// or forced after L cycles (000 §11-12; golden/texram/video/row_buffers.hpp, a cycle model;
// rtl/texram/tmu_video_rows.sv, hls/texram/video_rows_sc.hpp, docs/video.md).
//
// The block runs RowBuffers at 8-cell rows (segment_cells 8) and 8 buffers a bank, a read queue
// of 8 and 16-bit tags and waits. Channels (video_rows.json): cfg is L and the read bound; put
// (a cell write of a frame), flush (a frame ends), hold (the swap barrier: frames above the tag
// wait) and read (the line above, a segment read) give no output; an item of cycle is one
// memory cycle with whether the sampler wants it, and gives one output: whether the sampler got
// it, and the access that started in it (a write: bank, segment address, mask, cells, wait from
// ready; a read: bank, address, wait from request; each with its page fault). stat: cells in,
// lost writes, forced accesses, most buffers ready at once, most busy in a bank.
//
// The stimulus: frames of cell writes over a few pages of each bank, full and partial rows,
// with memory cycles between them at a sampler rate drawn per frame (idle to every cycle),
// reads of the line above, holds and their release, L from 0 to 64; some frames use more
// rows than a bank has (writes lost and counted).
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/video_rows/video_rows_ports.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "texram/video/row_buffers.hpp"

TMU_DESCRIBE(video_rows)

namespace tmu::tb {

// The block's RowBuffers configuration: 8-cell rows, 8 buffers a bank; and its read queue.
texram::video::ArbiterConfig video_rows_config(uint32_t max_wait, uint32_t read_wait);
inline constexpr size_t kVideoRowsReadQueue = 8;

class VideoRowsBlock : public DescribedBlockOf<VideoRowsBlock> {
 public:
  explicit VideoRowsBlock(const BlockOptions& options = {});
  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;

 private:
  BlockOptions options_;
  // cover() sees the items in order: the golden buffers over them.
  struct CoverState;
  mutable std::shared_ptr<CoverState> cover_;
};

}  // namespace tmu::tb
