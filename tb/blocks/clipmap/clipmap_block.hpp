// The clip-map address unit as a co-simulation block, `texsim cosim clipmap` (003;
// golden/clipmap/clipmap.hpp, rtl/texram/tmu_clipmap.sv, hls/texram/clipmap_sc.hpp).
//
// Channels (clipmap.json): req (virtual u, v SQ16.8, lambda, the shade) gives rgba; clut writes an
// entry; region writes a clipped level's valid region; load writes a texel of a level through the
// unit into the memory; cfg is the unit's configuration. The memory port carries the reads of every
// sample and the writes of every load, in order: golden predicts each, with the page model's
// counters, and the unit's counters of wayward samples (a substitution served them), substituted
// taps and bank conflicts.
//
// An environment: a virtual texture whose texel (level, x, y) is a hash of the environment's
// content seed, level and coordinates (every level its own random bytes: the unit moves texels,
// it does not filter levels into each other), and an eye. The stimulus writes the
// configuration, the CLUT, the centred tiles' regions (golden/clipmap/tile_centre.hpp) and loads
// every texel the clip-map holds; samples then fall mostly near the eye. The directed items tour
// the hard cases: taps straddling a tile's edge, the toroidal wrap, an eye jumping further than a
// tile (its tiles reloaded), the eye at the virtual texture's edge under each border mode, the
// boundary between the last clipped and the first whole level, lambda below 0 inside and outside
// the finest tile, loads and region writes right after samples, non-nested regions (conflicts),
// both substitution rules and the largest virtual texture (32k, with 4 x 4 tiles). A random run
// draws a new environment every few thousand items, and moves the eye (new regions and loads)
// now and then, as the host's tile manager does between frames.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/clipmap/clip_items.hpp"
#include "blocks/clipmap/clipmap_ports.hpp"
#include "blocks/registry.hpp"
#include "clipmap/clipmap.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(clipmap)

namespace tmu::tb {

class ClipmapBlock : public DescribedBlockOf<ClipmapBlock> {
 public:
  explicit ClipmapBlock(const BlockOptions& options = {});
  // A given clip-map (a render's): its setup items are the configuration alone (and a CLUT for
  // index textures, `clut`); the caller's items load it (clipmap::TileManager).
  ClipmapBlock(const clipmap::Config& config, const texram::Clut32& clut = {});
  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;

 private:
  // The configuration, CLUT, regions and loads that make the environment's clip-map.
  std::vector<Txn> environment_items(const ClipSetup& setup) const;
  std::vector<Txn> directed_samples(const ClipSetup& setup, std::mt19937_64& rng) const;

  ClipSetup first_;
  bool given_ = false;  // a render's clip-map: no content of the block's own
  texram::Clut32 clut_{};
  // cover() sees the items in order: the configuration and regions in effect.
  mutable size_t cover_next_ = 0;
  mutable clipmap::Config cover_config_;
  mutable clipmap::Regions cover_regions_{};
};

// An environment drawn from the generator: a small clip-map (the loads of a whole one fit a
// batch), every kind but CCC, filter, border modes, combine and substitution rule; the eye
// anywhere in the virtual texture and a little beyond.
ClipSetup draw_clip_setup(std::mt19937_64& rng);

// ---- Items: raw port values (clip_items.hpp's, for this block) ----------------------------

inline Txn clipmap_cfg_item(const clipmap::Config& config) {
  return clip_cfg_item<desc::clipmap>(config);
}
inline clipmap::Config clipmap_config_of(const Txn& cfg) {
  return clip_config_of<desc::clipmap>(cfg);
}
Txn clipmap_sample_item(int32_t u_raw, int32_t v_raw, int32_t lambda_raw, uint32_t shade = 0);
inline Txn clipmap_clut_item(uint8_t index, uint32_t rgba) {
  return clip_clut_item<desc::clipmap>(index, rgba);
}
inline Txn clipmap_region_item(int level, const clipmap::Region& region) {
  return clip_region_item<desc::clipmap>(level, region);
}
inline Txn clipmap_load_item(const clipmap::Load& load) {
  return clip_load_item<desc::clipmap>(load);
}
inline std::vector<Txn> clipmap_fill_items(const ClipSetup& setup, TexelOf texel_of) {
  return clip_fill_items<desc::clipmap>(setup, texel_of);
}

}  // namespace tmu::tb
