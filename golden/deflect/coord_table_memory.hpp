// The table memory behind the coordinate generator's write port (coord_tables.hpp, 001 §5),
// which the hls and rtl models (hls/deflect/coord_gen_sc.hpp, rtl/deflect/tmu_coord_gen.sv)
// and the co-simulation block load entry by entry, evaluated by eval_coords().
//
// The write port (what the unit does with a write; CoordTables only ever produces writes
// inside these rules, so its writes() load the memory exactly):
// - table ids beyond H3 (7), and addresses beyond their table (a theta table F1, F3, G3, H3
//   has Q entries, a phi table F2, G2, H2 has 2Q), change nothing;
// - the value is the port's low W bits as two's complement; -2^(W-1) is stored as
//   -(2^(W-1) - 1), the tables' range, so that negating an entry never overflows and
//   uN, vN, hN always fit SQ2.14 (|F1 F2 + F3| <= (2^(W-1) - 1)(2^W - 1) 2^-(2W-2) < 2);
// - the entries have no reset: they are undefined until written (this model starts at 0).
#pragma once

#include <algorithm>
#include <cstdint>

#include "deflect/coord_tables.hpp"

namespace tmu::deflect {

// The value a write stores: the port's low `value_bits` bits as two's complement, the most
// negative raised by one to the tables' range.
inline int32_t stored_coord_value(int32_t port_value, int value_bits) {
  const auto span = uint32_t{1} << value_bits;
  auto v = static_cast<int32_t>(static_cast<uint32_t>(port_value) & (span - 1));
  if (v >= static_cast<int32_t>(span / 2)) v -= static_cast<int32_t>(span);
  return std::max(v, -static_cast<int32_t>(span / 2 - 1));
}

// The unit's seven tables as the write port loads them (rules above).
class CoordTableMemory {
 public:
  explicit CoordTableMemory(const TableConfig& config) : config_(config) {
    for (int t = 0; t < kCoordTableCount; ++t) {
      tables_[t].assign(coord_table_size(config.grid, static_cast<CoordTable>(t)), 0);
    }
  }
  const TableConfig& config() const { return config_; }

  // Applies one write; false when it changes nothing (a table id or address beyond the tables).
  bool write(const TableWrite& w) {
    if (w.table >= kCoordTableCount || w.address >= tables_[w.table].size()) return false;
    tables_[w.table][w.address] = stored_coord_value(w.value, config_.value_bits);
    return true;
  }
  void load(const CoordTables& tables) {
    for (const TableWrite& w : tables.writes()) write(w);
  }

  int32_t entry(CoordTable table, uint32_t address) const { return tables_[table][address]; }
  const CoordTableData& data() const { return tables_; }
  MapCoords eval(SphereAngle normal) const { return eval_coords(config_, tables_, normal); }

 private:
  TableConfig config_;
  CoordTableData tables_;
};

}  // namespace tmu::deflect
