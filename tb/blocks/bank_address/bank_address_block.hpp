// The TEXRAM bank address unit as a co-simulation block, `texsim cosim bank_address`: a
// stored texel (or CCC block) position of a level and a byte plane -> its bank and cell address
// (000 §2, Fig. 2: "all address calculations ... performed locally"), exactly
// texram::Geometry::cell (golden/texram/layout.hpp; rtl/texram/tmu_bank_address.sv, the unit
// tmu_mipgen and tmu_trilinear instantiate).
//
// Channels (bank_address.json): in (level, x, y, plane) gives out (bank, addr) in the same
// cycle; cfg is the layout: log2 of the texture's sides, four byte planes or one, a block grid
// or texels. A position outside the layout is a stimulus error golden reports (the unit checks
// nothing). No hls level: no SystemC module computes addresses on its own (the trilinear and
// mipgen models use Geometry::cell, golden's); no icarus level (the generated testbench drives
// no cfg channel).
//
// The layout: the first drawn from the seed; the directed items visit the corners of every
// level and plane of layouts at the extremes (one texel, 1024 x 1024, rows, columns) with
// either grid and plane count; a random run draws a new layout every 1500 items.
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/bank_address/bank_address_ports.hpp"
#include "blocks/registry.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "texram/layout.hpp"

TMU_DESCRIBE(bank_address)

namespace tmu::tb {

class BankAddressBlock : public DescribedBlockOf<BankAddressBlock> {
 public:
  explicit BankAddressBlock(const BlockOptions& options = {});

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;

  // The configuration item of a layout, and the item of a position.
  static Txn config_item(const texram::Geometry& layout);
  static Txn position_item(int level, uint32_t x, uint32_t y, int plane);
  // The layout of a configuration item; throws std::invalid_argument for sides beyond 2^10.
  static texram::Geometry layout_of(const Txn& cfg);

 private:
  texram::Geometry first_{0, 0};
  // cover() sees the items in order: the layout in effect.
  mutable size_t cover_next_ = 0;
  mutable texram::Geometry cover_layout_{0, 0};
};

}  // namespace tmu::tb
