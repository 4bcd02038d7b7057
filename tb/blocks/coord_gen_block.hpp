// The shading- and environment-map coordinate generator as a co-simulation block
// (`texsim cosim coord-gen`; 001 §5, eq. 17-22; golden/deflect/coord_tables.hpp, evaluated on
// the tables the port loaded by golden/deflect/coord_table_memory.hpp).
//
// Input items: op 0 = table write (table, addr, value), op 1 = request (phi, theta).
// Output: un, vn, ur, vr, wr (SQ2.14), one per request. Items are applied in order: a request
// sees every write before it (the RTL reads its tables in the cycle it accepts the request).
//
// Stimulus: the setup loads every table from a view frame drawn from the seed (a random
// orthonormal side and up, dir = side x up; CoordTables::writes()). Directed: the angle
// corners (theta +-0 and the -0 input, the poles +-(Q-1); phi 0, Q, 2Q - 1, 2Q, 4Q - 1) on
// that frame; a write followed at once by a request reading the entry, for every table and
// both signs; the port's rules (-2^(W-1) stored as the limit, writes beyond a table
// ignored); view changes (the identity view and a mirrored axis frame, whose entries reach
// +-(2^(W-1) - 1)); tables filled through explicit writes with +-(2^(W-1) - 1) and 0, where
// uR, vR, wR saturate; then the seed's frame again. Random: uniform angles, one item in 64 a
// random table write, and a reload from a new random frame in the middle of every 16384
// items.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "deflect/coord_table_memory.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

enum CoordGenField { kCgOp, kCgTable, kCgAddr, kCgValue, kCgPhi, kCgTheta };
enum CoordGenOutField { kCgUn, kCgVn, kCgUr, kCgVr, kCgWr };
enum CoordGenOp : uint64_t { kCgOpWrite = 0, kCgOpRequest = 1 };

// A 128 x 64 grid with 8-bit entries (no rounding in the dot products): the parameters'
// other corner, verilated as Vtmu_coord_gen_a7w8.
inline constexpr deflect::TableConfig kCoordGenSmallConfig{deflect::SphereGrid{7}, 8};

class CoordGenBlock : public Block {
 public:
  // The rtl engine exists for the default config (the RTL's default parameters) and for
  // kCoordGenSmallConfig (a variant verilated with PhiBits = 7, ValueBits = 8).
  explicit CoordGenBlock(uint64_t seed, const deflect::TableConfig& config = {});

  std::string name() const override { return "coord-gen"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn& item) const override { return item.f[kCgOp] == kCgOpRequest; }
  std::vector<Txn> setup_items() const override;
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;

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

// The rtl engine for any Verilated model with the unit's ports (tests use mutants).
template <class Model>
std::unique_ptr<Engine> make_coord_gen_rtl_engine(const std::string& name);

}  // namespace tmu::tb

#include "blocks/coord_gen_rtl.inl"
