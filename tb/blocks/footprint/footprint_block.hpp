// Footprint assembly as a co-simulation block, `texsim cosim footprint`: a fragment's
// parallelogram footprint (r1 = d(u,v)/dx, r2 = d(u,v)/dy) approximated by N = 2^k trilinear
// probes along its longer side, averaged (000 §10, eq. 19-22; golden/footprint/footprint.hpp,
// rtl/footprint/tmu_footprint.sv, hls/footprint/footprint_sc.hpp).
//
// Channels (footprint.json): req (u, v TexCoord, r1u, r1v, r2u, r2v TexDeriv, the shade)
// gives one rgba each; clut writes an entry of its trilinear unit's CLUT; cfg is the trilinear
// unit's configuration and texture (the trilinear block's fields, in the same slots) and the
// setup's maximum probe count and q rule; the memory is the trilinear block's (every access
// predicted by golden, in order, with the page model's counters); stat_probes_o counts the
// probes.
//
// The environments are the trilinear block's (texram_setup.hpp, BlockOptions::tri_*), with the
// top-left quarter of level 0 painted white (every channel 255: the average's sums at their
// largest) in a texture built from a pattern or random bytes, and the setup's configuration
// (BlockOptions::fp_* fix what they set). The directed items tour every maximum probe count
// with both q rules and the trilinear configurations; a random run draws a new environment
// every few thousand items. The setup's widths (D, T, F) are the unit's parameters: rtl
// variants in rtl/blocks.cmake (the trilinear unit's widths 8,8,8 in every rtl model).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "blocks/footprint/footprint_ports.hpp"
#include "blocks/registry.hpp"
#include "blocks/trilinear/texram_sampler.hpp"
#include "blocks/trilinear/texram_setup.hpp"
#include "blocks/trilinear/texram_textures.hpp"
#include "blocks/trilinear/trilinear_block.hpp"
#include "footprint/footprint.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(footprint)

namespace tmu::tb {

// A given texture, how the trilinear unit samples it, and the setup's configuration (a scene's
// material); config.widths are the setup's.
struct FootprintEnv {
  TrilinearEnv trilinear;
  footprint::Config config;
};

// One environment: the trilinear unit's and the setup's configuration.
struct FootprintCfg {
  TexramSetup texram;
  footprint::Config setup;
};

class FootprintBlock : public DescribedBlockOf<FootprintBlock> {
 public:
  // The environments drawn from options.seed. Throws as TrilinearBlock does, and
  // std::invalid_argument for bad setup widths or a maximum probe count outside 0..4.
  explicit FootprintBlock(const BlockOptions& options);
  // On a given texture: its kind and size in every environment.
  FootprintBlock(const BlockOptions& options, FootprintEnv env);

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;
  std::string variant() const override;
  std::string repro_options() const override;

  // The first environment, and one line describing it.
  const FootprintCfg& first() const { return first_; }
  std::string describe() const;
  const std::shared_ptr<const TexramTextures>& textures() const { return textures_; }
  // The configuration item of an environment and, for index and CCC textures, its texture's
  // CLUT load: what a driver writes before sending fragments.
  std::vector<Txn> texture_load(const FootprintCfg& cfg) const;
  // The environment of a configuration item (the block's widths).
  FootprintCfg cfg_of(const Txn& cfg) const;

 private:
  FootprintCfg draw(std::mt19937_64& rng) const;
  std::vector<FootprintCfg> tour() const;
  std::vector<Txn> directed_fragments(const FootprintCfg& cfg) const;
  bool white_line_fits(const FootprintCfg& cfg) const;

  BlockOptions options_;
  std::shared_ptr<const TexramTextures> textures_;
  FootprintCfg first_;
  // cover() sees the items in order: the environment in effect and a golden trilinear unit
  // configured and written as the items before, for the probes' colours.
  mutable size_t cover_next_ = 0;
  mutable FootprintCfg cover_cfg_;
  mutable std::optional<TexramSampler> cover_unit_;
};

// Item constructors, for tests and tools: raw port values (SQ16.8: value * 256).
Txn footprint_sample_item(int32_t u, int32_t v, int32_t r1u, int32_t r1v, int32_t r2u, int32_t r2v,
                          uint32_t shade = 0xFFFF'FFFFu);
Txn footprint_clut_item(uint8_t index, uint32_t rgba);
// The request of a sample item (fields sign-extended), and the item of one.
footprint::Request footprint_request(const Txn& item);
Txn footprint_item(const footprint::Request& request);

}  // namespace tmu::tb
