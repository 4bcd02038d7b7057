// The footprint setup as a co-simulation block, `texsim cosim footprint_setup`: a fragment's
// derivative vectors -> N = 2^k probes, the marching direction and the probes' lambda (000 §10,
// eq. 19-22; golden footprint::plan, golden/footprint/footprint.hpp; rtl/footprint/
// tmu_footprint_setup.sv, the setup inside tmu_footprint).
//
// Channels (footprint_setup.json): req (the fragment) gives one plan each (the centre and
// shade as they came, the longer vector as it came, k, lambda); cfg is the maximum probe count
// and the q rule; stat busy (a fragment in a stage) must read 0 at the end. No hls level: the
// footprint unit's SystemC model plans inline with footprint::plan, golden's, and has no setup
// module of its own; no icarus level (the generated testbench drives no cfg channel). The
// widths (D, T, F) are the RTL's parameters; only the default is verilated on its own (the
// footprint block's variants run the others inside tmu_footprint).
//
// The fragments are the footprint block's (fragments.hpp) over a nominal 256 x 256 texture;
// the directed items visit every maximum probe count with both q rules; a random run draws a
// new configuration (BlockOptions::fp_* fix what they set) every few thousand items.
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/footprint_setup/footprint_setup_ports.hpp"
#include "blocks/registry.hpp"
#include "footprint/footprint.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(footprint_setup)

namespace tmu::tb {

class FootprintSetupBlock : public DescribedBlockOf<FootprintSetupBlock> {
 public:
  // Throws std::invalid_argument for bad widths or a maximum probe count outside 0..4.
  explicit FootprintSetupBlock(const BlockOptions& options);

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::string variant() const override;
  std::string repro_options() const override;

  // The configuration item of a setup configuration, and the configuration of one (the
  // block's widths).
  static Txn config_item(const footprint::Config& config);
  footprint::Config config_of(const Txn& cfg) const;
  // A fragment's item.
  static Txn fragment_item(const footprint::Request& request);

 private:
  BlockOptions options_;
  footprint::Config first_;
  // cover() sees the items in order: the configuration in effect.
  mutable size_t cover_next_ = 0;
  mutable footprint::Config cover_config_;
};

}  // namespace tmu::tb
