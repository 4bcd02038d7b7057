// The material unit as a co-simulation block, `texsim cosim material` (002 §4.2;
// golden/perlin/material_unit.hpp, whose MaterialUnit is the golden model): a register file
// and two colour tables behind a write port, and per sample the stages shape -> fractal ->
// colour (rtl/perlin/tmu_material.sv, hls/perlin/material_sc.hpp).
//
// Channels (material.json), items applied in order (a sample sees every write before it):
//   in   a sample: u, v, w (SolidCoord SQ12.12) -> rgb (RGB888)
//   wr   a write: wr_op 0 a register (reg: MaterialReg id, 12..15 ignored; value: 16 bits, a
//        value out of the register's range stored as its nearest limit,
//        MaterialUnit::write_reg), wr_op 1 a table entry (table: 0 main, 1 mortar; index:
//        beyond 127 ignored; rgb)
// The register writes are the block's configuration, but a host writes them between samples
// through the same handshake, so they stay a Write channel. Two RTL configurations with the
// same ports, chosen by BlockOptions::fractal_shared (`--fractal pipelined|shared`): the
// fractal unit pipelined (one sample per clock) or shared (one per 4 clocks); the hls model
// follows it.
//
// Stimulus: the setup loads a register set and both tables drawn from the seed. Directed:
// every material on the same coordinates (the kind switched by register writes mid-stream,
// negative coordinates and the SolidCoord extremes among them); marble's index wrap from 127
// to 0 (g_t = 0, g_v = 1.0) and the wrap of the sum with the turbulence term; fire at v <= 0,
// beyond its table and at every table entry, its index clamped at both ends; brick joints,
// the half-brick shift and the strict bounds on even, odd and negative rows and at the
// periods' extremes; cloud just below, at and above its cut-off, the gases' levels
// saturated; wood's rings at the extremes; register writes that saturate (kind, pw, ph, the
// mortars, also when a period shrinks) and unknown registers; a table write followed at once
// by a sample reading that entry, and writes beyond 127 that must not alias. Random: samples
// (uniform, near the origin, fire's range, lattice points, cell boundaries, large), one item
// in 32 a register write, one in 64 a table write, a new register set every 2048 items and new
// tables every 16384.
#pragma once

#include <bitset>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/material/material_ports.hpp"
#include "blocks/registry.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "perlin/material_unit.hpp"
#include "perlin/materials.hpp"

TMU_DESCRIBE(material)

namespace tmu::tb {

// Item constructors, for tests and the renderer. The value's low 16 bits (as write_reg), the
// table's bit 0, an index above 255 kept above 127 (ignored, as write_table), the low 24 bits
// of rgb and of each coordinate (SolidCoord).
Txn material_reg_item(perlin::MaterialReg reg, uint32_t value);
Txn material_table_item(uint32_t table, uint32_t index, uint32_t rgb);
Txn material_sample_item(int32_t u, int32_t v, int32_t w);
// Every register (pw and ph before the mortars, so that no mortar saturates against the
// previous periods) and both tables' 128 entries. Registers out of their ranges (check())
// are stored saturated.
std::vector<Txn> material_load_items(const perlin::MaterialRegs& regs,
                                     const perlin::ColourTables& tables);

// A register set and tables drawn from `rng` (every register in its range).
perlin::MaterialRegs random_material_regs(std::mt19937_64& rng);
perlin::ColourTables random_colour_tables(std::mt19937_64& rng);

class MaterialBlock : public DescribedBlockOf<MaterialBlock> {
 public:
  explicit MaterialBlock(const BlockOptions& options = {});

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::string variant() const override;

  bool shared() const { return shared_; }

 private:
  uint64_t seed_;
  bool shared_;
  // cover() replays the writes up to the sample it looks at.
  struct CoverState {
    const std::vector<Txn>* items = nullptr;
    size_t next = 0;
    perlin::MaterialUnit unit{};
    bool reg_write = false;       // a register write since the last sample
    bool kind_change = false;     // the kind changed since the last sample
    bool saturated = false;       // a register write stored its limit since the last sample
    bool mortar_clamped = false;  // a period write clamped a mortar since the last sample
    bool unknown_reg = false;     // a write to register 12..15 since the last sample
    bool ignored_entry = false;   // a table write beyond 127 since the last sample
    int64_t last_entry = -1;      // the previous sample's table entry (-1: none)
    std::bitset<perlin::kFireTableEntries> fire_k;
  };
  mutable CoverState cover_state_;
};

}  // namespace tmu::tb
