// Fire's e^-v table of the material unit as a co-simulation block, `texsim cosim
// material_fire` (002 §4.2.2): k (0..511) -> entry round(e^(-k/32) 2^12), UQ1.12, golden
// perlin::fire_entry (golden/perlin/materials.hpp). The RTL (rtl/perlin/tmu_material_fire.sv)
// builds the table at elaboration in integers only, golden with double exp(): the directed
// items read every entry. A combinational top: no clock, no reset, no hls level (the golden
// table is one function call; the material unit's hls model calls it).
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/material_fire/material_fire_ports.hpp"
#include "blocks/registry.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(material_fire)

namespace tmu::tb {

class MaterialFireBlock : public DescribedBlockOf<MaterialFireBlock> {
 public:
  explicit MaterialFireBlock(const BlockOptions& options = {});
  TMU_BLOCK_PIECES;

 private:
  // cover() sees every item in order: the indices read so far.
  mutable size_t cover_next_ = 0;
  mutable std::vector<bool> seen_;
};

}  // namespace tmu::tb
