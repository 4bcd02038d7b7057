// The bump deflection unit with its MBR as a co-simulation block, `texsim cosim deflect`:
// phi' = phi_D - theta_N, the octant reduction, one look-up of the first-octant
// spherical-to-spherical map through a one-block memory buffer register, the z = 0 column in
// closed form, the expansion and + phi_N (001 §4.4, §6.2; golden/deflect/s2s_map.hpp,
// rtl/deflect/tmu_deflect.sv, hls/deflect/deflect_sc.hpp).
//
// Input items: the normal (normal_phi: SpherePhi, normal_theta: SphereTheta) and the bump
// map's texel (bump_texel: Rgb888, which the unit unpacks to the angles phi_D, theta_D:
// deflect/bump_map.hpp). Output: the deflected normal (phi, theta) and the access
// (MapAccess: 0 hit, 1 miss, 2 bypass), so the cache's behaviour is compared bit for bit.
// Every miss requests its block from the map memory: golden predicts each request (the block
// address, in order) and its count, block_fetches; the timed runs add stall_cycles, the
// cycles a look-up waited for a block.
//
// The environment is the map (grid A = 9, computed once) in the map memory S2sMemory
// (tb/blocks/deflect/s2s_memory.hpp), which answers after BlockOptions::dfl_map_latency
// cycles plus 0..dfl_map_jitter drawn from the run's seed.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/deflect/deflect_ports.hpp"
#include "blocks/deflect/s2s_memory.hpp"
#include "blocks/registry.hpp"
#include "deflect/s2s_map.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(deflect)

namespace tmu::tb {

class DeflectBlock : public DescribedBlockOf<DeflectBlock> {
 public:
  explicit DeflectBlock(const BlockOptions& options = {});
  TMU_BLOCK_PIECES;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;
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

// An item from the normal's raw port values and the bump's angles (packed into its texel).
Txn deflect_item(deflect::SphereAngle normal, deflect::SphereAngle bump);
// An item from the normal's raw port values and a bump texel (Rgb888, any bits).
Txn deflect_texel_item(deflect::SphereAngle normal, uint32_t bump_texel);
// An item from angles in grid steps: theta as a signed count (zero is +0).
Txn deflect_steps_item(uint32_t normal_phi, int32_t normal_theta, uint32_t bump_phi,
                       int32_t bump_theta);
deflect::SphereAngle deflect_normal(const Txn& item);
// The bump's angles as the unit reads its texel.
deflect::SphereAngle deflect_bump(const Txn& item);
// The deflected normal of an output.
deflect::SphereAngle deflect_output(const Txn& output);

// Slowly varying normals and bumps, like a rasterizer's scanline over a bump-mapped surface:
// runs of 16..256 items whose angles move by at most a step at a time. Mostly hits.
std::vector<Txn> deflect_coherent_items(std::mt19937_64& rng, size_t count);

// The MBR's hits, misses and bypasses of a run, counted from its outputs' access codes (what a
// render reports of its deflection units).
Counters map_access_counters(const std::vector<Txn>& outputs);

}  // namespace tmu::tb
