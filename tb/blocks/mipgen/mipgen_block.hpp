// The TEXRAM mipmap generator as a co-simulation block, `texsim cosim mipgen`: level-0 texels
// of whole frames in, bank-cell writes of every level out (000 §12, Fig. 14;
// golden/texram/mipgen_stream.hpp, rtl/texram/tmu_mipgen.sv, hls/texram/mipgen_sc.hpp).
//
// Channels (mipgen.json): cfg is the frame format (log2 width and height 0..10,
// interlaced, one or four byte planes and the plane filled), written between frames as a video
// driver does; in takes one level-0 texel per item in source order, with the texel above it in
// interlaced field 2 (0 elsewhere); wr gives the writes (level, stored x and y, value, bank,
// address). An item makes one or more writes (its level-0 write and replicas, then each
// higher-level texel it completes), so in is a Stream channel: golden counts them and names
// the item behind every write.
//
// The stimulus starts with the configuration item of the seed's format. The directed items
// run a list of formats (1 x 1, one texel wide or high, interlaced, non-square, 1024-texel
// lines and columns), each with frames of zeros, of 255, alternating, of rounding ties or
// random; the random items are whole random frames, a new format every one to three frames,
// small ones (at most 1024 texels). BlockOptions::mip_log2_w, mip_log2_h and mip_interlaced
// fix those parts of every format (large frames too).
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/mipgen/mipgen_frames.hpp"
#include "blocks/mipgen/mipgen_ports.hpp"
#include "blocks/registry.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(mipgen)

namespace tmu::tb {

class MipgenBlock : public DescribedBlockOf<MipgenBlock> {
 public:
  // options.seed draws the formats; options.mip_* fix their parts (std::invalid_argument
  // when out of range).
  explicit MipgenBlock(const BlockOptions& options = {});

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::string repro_options() const override;

 private:
  // `f` with the parts the options fix.
  texram::MipgenConfig fixed(texram::MipgenConfig f) const;
  texram::MipgenConfig draw_format(std::mt19937_64& rng) const;

  BlockOptions options_;
  texram::MipgenConfig first_;
  // cover() sees the items in order: the golden stream over them, and the writes of the item
  // it covers.
  struct CoverState {
    MipgenFrames frames;
    size_t next = 0;
    std::vector<texram::CellWrite> writes;
  };
  mutable CoverState cover_;
};

}  // namespace tmu::tb
