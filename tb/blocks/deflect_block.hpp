// The bump deflection unit with its MBR as a co-simulation block (`texsim cosim deflect`):
// phi' = phi_D - theta_N, the octant reduction, one look-up of the first-octant
// spherical-to-spherical map through a one-block memory buffer register, the z = 0 column in
// closed form, the expansion and + phi_N (001 §4.4, §6.2; golden/deflect/s2s_map.hpp).
//
// Input items: the normal (normal_phi: SpherePhi, normal_theta: SphereTheta) and the bump
// texel (bump_phi, bump_theta). Output: the deflected normal (phi, theta) and the access
// (MapAccess: 0 hit, 1 miss, 2 bypass), so the cache's behaviour is compared bit for bit.
// Counters: hits, misses, bypasses (of the results), block_fetches (the map memory's
// requests); the hls and rtl runs add stall_cycles, the cycles a look-up waited for a block.
//
// The environment is the map (grid A = 9, computed once) in the map memory S2sMemory
// (tb/blocks/s2s_memory.hpp), which answers after BlockOptions::dfl_map_latency cycles plus
// 0..dfl_map_jitter drawn from the seed; the golden model reads the map directly.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>

#include "blocks/registry.hpp"
#include "blocks/s2s_memory.hpp"
#include "deflect/s2s_map.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

enum DeflectField { kDflNormalPhi, kDflNormalTheta, kDflBumpPhi, kDflBumpTheta };
enum DeflectOutField { kDflOutPhi, kDflOutTheta, kDflOutAccess };

class DeflectBlock : public Block {
 public:
  explicit DeflectBlock(const BlockOptions& options);

  std::string name() const override { return "deflect"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn&) const override { return true; }
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;
  std::string repro_options() const override;

  const std::shared_ptr<const deflect::S2sMap>& map() const { return map_; }
  S2sMemoryTiming timing() const { return timing_; }

 private:
  std::shared_ptr<const deflect::S2sMap> map_;
  S2sMemoryTiming timing_;
  // cover() keeps the last two look-ups' blocks and access codes (it sees every item in order).
  struct Recent {
    bool valid = false;
    bool bypass = false;
    uint32_t block = 0;
    deflect::MapAccess access = deflect::MapAccess::kHit;
  };
  mutable size_t cover_next_ = 0;
  mutable Recent cover_prev_, cover_prev2_;
  mutable bool cover_looked_up_ = false;  // a look-up (not a bypass) came before
};

// An item from the angles' raw port values.
Txn deflect_item(deflect::SphereAngle normal, deflect::SphereAngle bump);
// An item from angles in grid steps: theta as a signed count (zero is +0).
Txn deflect_steps_item(uint32_t normal_phi, int32_t normal_theta, uint32_t bump_phi,
                       int32_t bump_theta);
deflect::SphereAngle deflect_normal(const Txn& item);
deflect::SphereAngle deflect_bump(const Txn& item);

// Slowly varying normals and bumps, like a rasterizer's scanline over a bump-mapped surface:
// runs of 16..256 items whose angles move by at most a step at a time. Mostly hits.
std::vector<Txn> deflect_coherent_items(std::mt19937_64& rng, size_t count);

// The rtl engine for any Verilated model with the unit's ports (tests use mutants).
template <class Model>
std::unique_ptr<Engine> make_deflect_rtl_engine(const std::string& name,
                                                std::shared_ptr<const deflect::S2sMap> map,
                                                S2sMemoryTiming timing);

}  // namespace tmu::tb

#include "blocks/deflect_rtl.inl"
