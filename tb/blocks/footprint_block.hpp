// Footprint assembly as a co-simulation block (`texsim cosim footprint`): a fragment's
// parallelogram footprint (r1 = d(u,v)/dx, r2 = d(u,v)/dy) approximated by N = 2^k trilinear
// probes along its longer side, averaged (000 §10, eq. 19-22; golden/footprint/footprint.hpp).
//
// Items, outputs and counters as tb/blocks/footprint_env.hpp says. The environment is the
// trilinear block's (a texture in the TEXRAM's banks and the unit's configuration,
// make_trilinear_env from the tri_* options), with the top-left quarter of level 0 painted
// white (all channels 255: the average's sums at their largest) unless the texture is an
// image file, and the setup's configuration: maximum probes and q rule drawn from the seed
// unless BlockOptions::fp_* sets them, widths from fp_widths.
//
// Engines: golden (footprint::sample per item, CLUT writes applied to a copy of the texture,
// every probe's plan fed to a TexramAccessLog), rtl (the Verilated tmu_footprint with the
// memory of the trilinear block), hls (tb/blocks/footprint_hls.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/footprint_env.hpp"
#include "blocks/registry.hpp"
#include "blocks/trilinear_block.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

// The environment of `options`: the trilinear environment (make_trilinear_env), the white
// quarter painted, and the setup's configuration (fp_* set, the rest drawn from options.seed).
// Throws as make_trilinear_env does, and std::invalid_argument for bad footprint widths or
// a maximum probe count outside 0..4.
FootprintEnv make_footprint_env(const BlockOptions& options);

class FootprintBlock : public Block {
 public:
  explicit FootprintBlock(const BlockOptions& options);
  FootprintBlock(const BlockOptions& options, FootprintEnv env);

  std::string name() const override { return "footprint"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn& item) const override { return item.f[kFpOp] == kFpOpSample; }
  std::vector<Txn> setup_items() const override;
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;
  std::string repro_options() const override;

  const FootprintEnv& env() const { return env_; }
  // One line: the trilinear environment, maximum probes, q rule, setup widths.
  std::string describe() const;

 private:
  BlockOptions options_;
  FootprintEnv env_;
  TrilinearBlock trilinear_;  // describes the trilinear environment and its options
  // cover() replays the CLUT writes up to the item it looks at (the probes' colours).
  struct CoverState {
    const std::vector<Txn>* items = nullptr;
    size_t next = 0;
    std::shared_ptr<texram::TexramTexture> texture;
  };
  mutable CoverState cover_state_;
};

// Item constructors, for tests and tools: raw port values (SQ16.8: value * 256).
Txn footprint_sample_item(int32_t u, int32_t v, int32_t r1u, int32_t r1v, int32_t r2u, int32_t r2v,
                          uint32_t shade = 0xFFFF'FFFFu);
Txn footprint_clut_item(uint8_t index, uint32_t rgba);
// The request of a sample item (fields sign-extended).
footprint::Request footprint_request(const Txn& item);

// The rtl engine for any Verilated model with the unit's ports (tests use mutants and the
// width variants: env.config.widths must be the model's, env.trilinear.config.widths 8,8,8).
template <class Model>
std::unique_ptr<Engine> make_footprint_rtl_engine(const std::string& name, FootprintEnv env);

}  // namespace tmu::tb

#include "blocks/footprint_rtl.inl"
