// Golden model of the shading- and environment-map coordinate generator (001 §5,
// eq. 17-22): seven small tables indexed by the (deflected) normal's angles give
//   uN = N . v_side = F1(theta) F2(phi) + F3(theta)      (eq. 17, 19)
//   vN = N . v_up   = F1(theta) G2(phi) + G3(theta)      (eq. 18, 20)
//   hN = N . v_dir  = F1(theta) H2(phi) + H3(theta)      (eq. 22)
//   uR = 2 hN uN,  vR = 2 hN vN                          (eq. 21: R = 2 (N.E) N - E, E = v_dir)
//   wR = R . v_dir = 2 hN^2 - 1                          (the third component, for the cube map)
// with F1 = G1 = H1 = cos(theta), F2(phi) = sin(phi) side_x + cos(phi) side_z, F3(theta) =
// sin(theta) side_y, and G, H likewise with v_up and v_dir. v_side, v_up, v_dir are the view
// frame in object space (v_dir = v_side x v_up points towards the viewer); the host
// recomputes the tables when the view or the object's orientation changes, and loads them
// through the unit's write port. This file is the specification the hls and rtl models match.
//
// Tables (W = value_bits, values SQ1.(W-1) rounded half up and saturated to +-(2^(W-1) - 1)
// so that negation never overflows):
//   theta tables (F1, F3, G3, H3): Q entries, indexed by |theta| (0 .. Q-1 steps); F1 is even
//     in theta, F3, G3, H3 odd (negated for a negative theta).
//   phi tables (F2, G2, H2): 2Q entries for phi = 0 .. 180 degrees; phi >= 2Q reads entry
//     phi - 2Q negated (F2(phi + pi) = -F2(phi)). The paper's 128 entries (0 .. 90 degrees)
//     cannot hold these: a sin(phi) + b cos(phi) has no quarter-wave symmetry unless a or b
//     is zero. 3 x 2Q + 4 x Q = 1280 entries for the 512 x 256 grid.
// Evaluation: the products and sums are exact (2W - 2 fraction bits), uN, vN, hN are rounded
// half up to UnitComp SQ2.14; uR, vR, wR from those (exact products, rounded half up to
// SQ2.14, saturated).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "deflect/sphere_grid.hpp"
#include "deflect/view_frame_definition.hpp"

namespace tmu::deflect {

struct TableConfig {
  SphereGrid grid;
  int value_bits = 10;  // W, 8..16
  friend bool operator==(const TableConfig&, const TableConfig&) = default;
};

enum CoordTable : uint8_t { kF1, kF2, kF3, kG2, kG3, kH2, kH3, kCoordTableCount };
bool is_phi_table(CoordTable table);

// One write of the unit's table port.
struct TableWrite {
  uint8_t table = 0;
  uint32_t address = 0;
  int32_t value = 0;  // SQ1.(W-1)
};

struct MapCoords {
  int32_t un = 0, vn = 0;          // shading-map coordinates, SQ2.14
  int32_t ur = 0, vr = 0, wr = 0;  // reflection vector in the view frame, SQ2.14
};

// One vector per table (F1, F2, F3, G2, G3, H2, H3).
using CoordTableData = std::array<std::vector<int32_t>, kCoordTableCount>;

// Entries of a table: Q for the theta tables, 2Q for the phi tables.
uint32_t coord_table_size(const SphereGrid& grid, CoordTable table);

// uN, vN, hN, uR, vR, wR of `normal` from any table contents (the evaluation above). An odd
// table's entry is negated whenever theta's sign bit is set: -0 reads as zero because the
// odd tables hold sin(0) = 0 at |theta| = 0.
MapCoords eval_coords(const TableConfig& config, const CoordTableData& tables, SphereAngle normal);

class CoordTables {
 public:
  CoordTables(const TableConfig& config, const ViewFrame& view);
  const TableConfig& config() const { return config_; }
  // Every entry as the unit's port loads it, table by table.
  std::vector<TableWrite> writes() const;
  int32_t entry(CoordTable table, uint32_t address) const { return tables_[table][address]; }
  MapCoords eval(SphereAngle normal) const;

 private:
  TableConfig config_;
  CoordTableData tables_;
};

}  // namespace tmu::deflect
