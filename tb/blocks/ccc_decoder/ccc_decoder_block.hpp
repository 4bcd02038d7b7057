// The CCC decoder as a co-simulation block, `texsim cosim ccc_decoder` (alias ccc): a block
// word and a texel address (4 y + x) -> the texel's decision bit -> colour index a or b -> the
// 256 x RGB888 colour look-up table (000 §3, Fig. 5; golden/ccc/ccc_decoder.hpp,
// rtl/ccc/tmu_ccc_decoder.sv, hls/ccc/ccc_decoder_sc.hpp).
//
// Channels (ccc_decoder.json): req (block, texel) gives one rgb each; clut writes an entry
// and gives none. The CLUT is a RAM without reset: the stimulus starts with the load of every
// entry (colours drawn from the seed), and golden rejects a decode of an entry never written.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/ccc_decoder/ccc_decoder_ports.hpp"
#include "blocks/registry.hpp"
#include "ccc/ccc_texture.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(ccc_decoder)

namespace tmu::tb {

class CccDecoderBlock : public DescribedBlockOf<CccDecoderBlock> {
 public:
  // options.seed draws the colours of the CLUT load.
  explicit CccDecoderBlock(const BlockOptions& options = {});
  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;

 private:
  uint64_t seed_;
};

// Item constructors, for tests and tools.
Txn decode_item(uint32_t block_word, unsigned texel);
Txn clut_write_item(uint8_t index, uint32_t rgb);

// Decodes every texel of `tex` through a decoder engine (CLUT load, then the texels in
// row-major order, no stalls). `run` receives the engine's run (timing, errors).
ImageRgb8 decode_with_engine(const ccc::Texture& tex, Engine& engine, RunResult* run = nullptr);

}  // namespace tmu::tb
