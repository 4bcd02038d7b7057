// Footprint assembly on a clip-map as a co-simulation block, `texsim cosim footprint_clip`
// (000 §10 in front of 003; golden/clipmap/clip_footprint.hpp,
// rtl/footprint/tmu_footprint_clip.sv, hls/footprint/footprint_clip_sc.hpp): the footprint
// unit's fragments, each marched into N probes that read the clip-map like any sample.
//
// Channels (footprint_clip.json): req (u, v virtual TexCoord, r1, r2 TexDeriv, the shade) gives
// one rgba each; clut, region and load are the clip-map's writes; cfg is the clip-map's
// configuration and the setup's maximum probe count and q rule. The memory port carries every
// probe's reads and every load's writes, predicted by golden in order with the page model's
// counters; the counters are the probes and the clip-map's (per probe).
//
// The environments are the clip-map block's (clipmap_block.hpp: a hashed virtual texture, the
// tiles centred on an eye and loaded whole) with the setup's configuration drawn as the
// footprint block draws it (fragments.hpp). The directed items: the footprint block's directed
// fragments over the virtual texture; long footprints from the eye across every clipped
// level's tile edges along each axis and the diagonal (some probes held, the far ones
// wayward); a tour of both substitution rules under every border mode with the eye at the
// virtual texture's corners, and the 32k virtual texture; writes between fragments. A random
// run draws a new environment every few thousand items and moves the eye now and then.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/clipmap/clip_items.hpp"
#include "blocks/footprint_clip/footprint_clip_ports.hpp"
#include "blocks/registry.hpp"
#include "footprint/footprint.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(footprint_clip)

namespace tmu::tb {

// One environment: the clip-map's and the setup's.
struct FootprintClipSetup {
  ClipSetup clip;
  footprint::Config setup;
};

class FootprintClipBlock : public DescribedBlockOf<FootprintClipBlock> {
 public:
  // Throws std::invalid_argument for bad setup widths or a maximum probe count outside 0..4.
  explicit FootprintClipBlock(const BlockOptions& options = {});
  // A given clip-map and setup (a render's): its setup items are the configuration alone (and a
  // CLUT for index textures); the caller's items load it (clipmap::TileManager).
  FootprintClipBlock(const clipmap::Config& clip, const footprint::Config& setup,
                     const texram::Clut32& clut = {});
  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;
  std::string variant() const override;
  std::string repro_options() const override;

 private:
  FootprintClipSetup draw(std::mt19937_64& rng) const;
  std::vector<Txn> environment_items(const FootprintClipSetup& setup) const;
  std::vector<Txn> directed_fragments(const FootprintClipSetup& setup) const;

  BlockOptions options_;
  FootprintClipSetup first_;
  bool given_ = false;  // a render's clip-map: no content of the block's own
  texram::Clut32 clut_{};
  // cover() sees the items in order: the configuration and regions in effect.
  mutable size_t cover_next_ = 0;
  mutable FootprintClipSetup cover_setup_;
  mutable clipmap::Regions cover_regions_{};
};

// Items: raw port values. The configuration item of an environment, and a fragment's.
Txn footprint_clip_cfg_item(const clipmap::Config& clip, const footprint::Config& setup);
Txn footprint_clip_item(const footprint::Request& request);

}  // namespace tmu::tb
