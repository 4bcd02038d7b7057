#include "deflect/coord_tables.hpp"

#include <algorithm>
#include <cmath>

namespace tmu::deflect {
namespace {

constexpr int kCoordFrac = 14;  // UnitComp SQ2.14

int32_t quantize(double v, int value_bits) {
  const int64_t limit = (int64_t{1} << (value_bits - 1)) - 1;
  const auto raw = static_cast<int64_t>(std::floor(std::ldexp(v, value_bits - 1) + 0.5));
  return static_cast<int32_t>(std::clamp(raw, -limit, limit));
}

int64_t round_shift(int64_t v, int shift) {
  return shift == 0 ? v : (v + (int64_t{1} << (shift - 1))) >> shift;
}

int32_t saturate_coord(int64_t v) {
  return static_cast<int32_t>(std::clamp<int64_t>(v, -(1 << 15), (1 << 15) - 1));
}

}  // namespace

bool is_phi_table(CoordTable table) { return table == kF2 || table == kG2 || table == kH2; }

CoordTables::CoordTables(const TableConfig& config, const ViewFrame& view) : config_(config) {
  const uint32_t q = config.grid.quarter();
  const double d = config.grid.step();
  const int w = config.value_bits;
  const auto phi_table = [&](const std::array<double, 3>& a) {
    std::vector<int32_t> t(2 * q);
    for (uint32_t i = 0; i < 2 * q; ++i)
      t[i] = quantize(std::sin(i * d) * a[0] + std::cos(i * d) * a[2], w);
    return t;
  };
  const auto theta_table = [&](double scale, bool cosine) {
    std::vector<int32_t> t(q);
    for (uint32_t m = 0; m < q; ++m)
      t[m] = quantize(cosine ? std::cos(m * d) : std::sin(m * d) * scale, w);
    return t;
  };
  tables_[kF1] = theta_table(1.0, true);
  tables_[kF2] = phi_table(view.side);
  tables_[kF3] = theta_table(view.side[1], false);
  tables_[kG2] = phi_table(view.up);
  tables_[kG3] = theta_table(view.up[1], false);
  tables_[kH2] = phi_table(view.dir);
  tables_[kH3] = theta_table(view.dir[1], false);
}

std::vector<TableWrite> CoordTables::writes() const {
  std::vector<TableWrite> out;
  for (int t = 0; t < kCoordTableCount; ++t) {
    for (uint32_t a = 0; a < tables_[t].size(); ++a) {
      out.push_back({static_cast<uint8_t>(t), a, tables_[t][a]});
    }
  }
  return out;
}

MapCoords CoordTables::eval(SphereAngle normal) const {
  return eval_coords(config_, tables_, normal);
}

uint32_t coord_table_size(const SphereGrid& grid, CoordTable table) {
  return is_phi_table(table) ? 2 * grid.quarter() : grid.quarter();
}

MapCoords eval_coords(const TableConfig& config, const CoordTableData& tables, SphereAngle normal) {
  const SphereGrid& g = config.grid;
  const uint32_t q = g.quarter();
  const int w = config.value_bits;
  const uint32_t m = theta_mag(g, normal.theta);
  const bool theta_neg = theta_negative(g, normal.theta);
  const uint32_t p = normal.phi & g.phi_mask();
  const bool phi_neg = p >= 2 * q;
  const uint32_t pi = phi_neg ? p - 2 * q : p;

  const int64_t c = tables[kF1][m];
  const auto odd_theta = [&](CoordTable t) {
    return int64_t{theta_neg ? -tables[t][m] : tables[t][m]};
  };
  const auto odd_phi = [&](CoordTable t) {
    return int64_t{phi_neg ? -tables[t][pi] : tables[t][pi]};
  };
  const int shift = 2 * w - 2 - kCoordFrac;
  const auto dot = [&](CoordTable t2, CoordTable t3) {
    return round_shift(c * odd_phi(t2) + (odd_theta(t3) << (w - 1)), shift);
  };
  MapCoords out;
  const int64_t un = dot(kF2, kF3), vn = dot(kG2, kG3), hn = dot(kH2, kH3);
  out.un = static_cast<int32_t>(un);
  out.vn = static_cast<int32_t>(vn);
  // 2 a b in SQ2.14: the product has 28 fraction bits, times two is a shift by 13.
  out.ur = saturate_coord(round_shift(hn * un, kCoordFrac - 1));
  out.vr = saturate_coord(round_shift(hn * vn, kCoordFrac - 1));
  out.wr = saturate_coord(round_shift(hn * hn, kCoordFrac - 1) - (1 << kCoordFrac));
  return out;
}

}  // namespace tmu::deflect
