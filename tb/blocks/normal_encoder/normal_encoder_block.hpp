// The normal encoder as a co-simulation block, `texsim cosim normal_encoder` (alias
// normal-encoder): an unnormalised Cartesian normal (x, y, z) UnitComp SQ2.14 to its angles
// phi (SpherePhi) and theta (SphereTheta) on the sphere grid (001 §4.1, eq. 12-16;
// golden/deflect/normal_encoder.hpp, rtl/deflect/tmu_normal_encoder.sv,
// hls/deflect/normal_encoder_sc.hpp).
//
// The encoder's widths are BlockOptions::encoder (`--encoder S,E,M`; grid A = 9, the ports'):
// golden, hls and icarus (the widths reach the RTL as Verilog parameters) take any, the rtl
// level only the verilated variants of rtl/blocks.cmake (the default and the paper's linear
// index E = 1, M = 7): at other widths the block has no rtl level.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "blocks/normal_encoder/normal_encoder_ports.hpp"
#include "blocks/registry.hpp"
#include "deflect/normal_encoder.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(normal_encoder)

namespace tmu::tb {

class NormalEncoderBlock : public DescribedBlockOf<NormalEncoderBlock> {
 public:
  explicit NormalEncoderBlock(const BlockOptions& options = {});
  TMU_BLOCK_PIECES;
  // The verilated widths' key ("" the default, "e1m7"), or "s<S>e<E>m<M>" (no rtl model).
  std::string variant() const override;
  std::string repro_options() const override;

  const deflect::EncoderConfig& config() const { return encoder_->config(); }

 private:
  std::shared_ptr<const deflect::NormalEncoder> encoder_;
  // The angle-table indices some ratio reaches.
  std::shared_ptr<const std::set<uint32_t>> reachable_angle_;
  // cover() collects the table indices seen so far (it sees every item in order).
  mutable size_t cover_next_ = 0;
  mutable std::set<uint32_t> seen_angle_[2], seen_seed_[2];  // [0] phi, [1] theta
};

// An item from the components' values, and the components of an item.
Txn normal_item(int16_t x, int16_t y, int16_t z);
int16_t normal_x(const Txn& item);
int16_t normal_y(const Txn& item);
int16_t normal_z(const Txn& item);

// The divider's seed-table index for a denominator (golden divide_ratio's i; 0 for den = 0).
uint32_t encoder_seed_index(uint32_t den, int seed_bits);
// Every angle-table index some ratio t = 1 .. 2^16 reads (t = 0 reads none; for e < E - 1 the
// index's top two mantissa bits are never both zero: those entries are dead).
std::set<uint32_t> reachable_angle_indices(const deflect::EncoderConfig& config);

}  // namespace tmu::tb
