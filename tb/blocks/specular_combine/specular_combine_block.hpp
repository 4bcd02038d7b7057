// The specular combine as a co-simulation block, `texsim cosim specular_combine` (alias
// specular-combine): the diffusely shaded texture colour plus the reflectance times the
// environment or specular sample, per channel saturated at 255, alpha from the diffuse colour
// (000 §7 eq. 6, §8 eq. 7; golden/texram/specular_combine.hpp,
// rtl/texram/tmu_specular_combine.sv, hls/texram/specular_combine_sc.hpp).
//
// Channels (specular_combine.json): in (diffuse D, specular E, reflectance R, each
// RGBA8888) gives one colour C (RGBA8888) each.
#pragma once

#include <bitset>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/specular_combine/specular_combine_ports.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(specular_combine)

namespace tmu::tb {

class SpecularCombineBlock : public DescribedBlockOf<SpecularCombineBlock> {
 public:
  explicit SpecularCombineBlock(const BlockOptions& options = {});
  TMU_BLOCK_PIECES;

 private:
  // cover() sees every item in order; the (e, r) pairs seen so far in R, G, B (index e 256 + r).
  mutable size_t cover_next_ = 0;
  mutable std::bitset<65536> seen_pairs_[3];
  mutable size_t seen_count_[3] = {};
};

// An item from the three colours (0xRRGGBBAA each); the renderer builds its items with it.
Txn specular_combine_item(uint32_t diffuse, uint32_t specular, uint32_t reflectance);

}  // namespace tmu::tb
