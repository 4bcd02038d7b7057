// The shading- and environment-map coordinate generator as a co-simulation block, `texsim
// cosim coord_gen` (alias coord-gen; 001 §5, eq. 17-22; golden/deflect/coord_tables.hpp,
// evaluated on the tables the port loaded by golden/deflect/coord_table_memory.hpp;
// rtl/deflect/tmu_coord_gen.sv, hls/deflect/coord_gen_sc.hpp).
//
// Channels: tw, a table write (table, addr, value SQ1.9: no output); in, a request (phi,
// theta) giving un, vn, ur, vr, wr (SQ2.14). Items are applied in order: a request sees every
// write before it (the RTL reads its tables in the cycle it accepts the request).
//
// The tables' grid and entry width are BlockOptions::coord_tables (`--coord-tables A,W`):
// golden, hls and icarus take any the ports carry (A 6..9, W 8..10), the rtl level only the
// verilated variants of rtl/blocks.cmake (9,10 and 7,8): at others the block has no rtl level.
//
// Stimulus: the setup loads every table (they have no reset) from a view frame drawn from the
// seed (a random orthonormal side and up, dir = side x up; CoordTables::writes()). Directed:
// the angle corners (theta +-0 and the -0 input, the poles +-(Q-1); phi 0, Q, 2Q - 1, 2Q,
// 4Q - 1) on that frame; a write followed at once by a request reading the entry, for every
// table and both signs; the port's rules (-2^(W-1) stored as the limit, writes beyond a
// table ignored); view changes (the identity view and a mirrored axis frame, whose entries
// reach +-(2^(W-1) - 1)); tables filled through explicit writes with +-(2^(W-1) - 1) and 0,
// where uR, vR, wR saturate; then the seed's frame again. Random: uniform angles, one item in
// 64 a random table write, and a reload from a new random frame in the middle of every 16384
// items.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/coord_gen/coord_gen_ports.hpp"
#include "blocks/registry.hpp"
#include "deflect/coord_table_memory.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(coord_gen)

namespace tmu::tb {

class CoordGenBlock : public DescribedBlockOf<CoordGenBlock> {
 public:
  explicit CoordGenBlock(const BlockOptions& options = {});
  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  // "" for the default tables, else "a<A>w<W>" (a key of rtl/blocks.cmake where verilated).
  std::string variant() const override;
  std::string repro_options() const override;

  // The grid and width of the tables.
  const deflect::TableConfig& config() const { return config_; }

 private:
  uint64_t seed_;
  deflect::TableConfig config_;
  // cover() replays the writes up to the item it looks at (the entries a request reads).
  struct CoverState {
    const std::vector<Txn>* items = nullptr;
    size_t next = 0;
    std::shared_ptr<deflect::CoordTableMemory> tables;
    size_t writes_since_request = 0;
    bool min_value_written = false;  // a write of -2^(W-1) since the last request
    bool ignored_write = false;      // a write beyond the tables since the last request
  };
  mutable CoverState cover_state_;
};

// Item constructors, for tests and tools (raw port values; value SQ1.9).
Txn coord_write_item(uint8_t table, uint32_t address, int32_t value);
Txn coord_request_item(uint32_t phi, uint32_t theta);
// An output's coordinates, sign-extended.
deflect::MapCoords coord_gen_output(const Txn& output);
// Every entry of `tables` as write items, table by table (CoordTables::writes()).
std::vector<Txn> coord_load_items(const deflect::CoordTables& tables);
// A view frame drawn from `rng`: side and up orthonormal and uniformly oriented, dir = side x up.
deflect::ViewFrame random_view_frame(std::mt19937_64& rng);

}  // namespace tmu::tb
