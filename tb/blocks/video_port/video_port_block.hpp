// The TEXRAM's video port receiver as a co-simulation block, `texsim cosim video_port`: items
// of a serial video stream in (four flags and the texel's bytes), per item the receiver's
// verdict out: its place in the frame, frame start and end, a frame dropped before it, its
// error; and the receiver's counters (000 §11; golden/texram/video/video_port.hpp,
// rtl/texram/tmu_video_port.sv, hls/texram/video_port_sc.hpp, docs/video.md).
//
// Channels (video_port.json): cfg is the frame format (log2 width and height 0..10,
// interlaced, four planes), written between frames; in takes one item (flags, texel); out
// gives one verdict per item; stat the five ReceiverStats counters (32 bits, wrapping).
//
// The stimulus: whole frames of test_frame's pictures in source order, well formed or with
// one defect (a texel missing or added on a line, a frame cut short, the fields swapped,
// random flags), formats from 1 x 1 to a 1024-texel line, progressive and interlaced, one and
// four planes; now and then a new format written in the middle of a frame.
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/video_port/video_port_ports.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "texram/video/video_port.hpp"

TMU_DESCRIBE(video_port)

namespace tmu::tb {

class VideoPortBlock : public DescribedBlockOf<VideoPortBlock> {
 public:
  explicit VideoPortBlock(const BlockOptions& options = {});
  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;

 private:
  BlockOptions options_;
  // cover() sees the items in order: the golden receiver over them.
  struct CoverState {
    texram::video::VideoReceiver rx{texram::video::VideoFormat{}};
    size_t next = 0;
    bool changed_in_frame = false;  // the last configuration dropped a frame under way
  };
  mutable CoverState cover_;
};

// The configuration item of a format, and an item as the in channel carries it.
Txn video_port_config_item(const texram::video::VideoFormat& format);
Txn video_port_item(const texram::video::VideoItem& item);
// The items of frame number k of test_frame's video of `format`, in source order.
std::vector<Txn> video_port_frame(const texram::video::VideoFormat& format, uint32_t k);

}  // namespace tmu::tb
