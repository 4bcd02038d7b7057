#include "blocks/coord_gen/coord_gen_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>

#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/deflect/coord_gen_sc.hpp"
#include "rtl_models_coord_gen.hpp"

TMU_DESCRIBE_SC(coord_gen)

namespace tmu::tb {
namespace fmts = tmu::formats;
using deflect::CoordTable;
using deflect::CoordTables;
using deflect::MapCoords;
using deflect::SphereAngle;
using deflect::TableConfig;
using deflect::ViewFrame;
using D = desc::coord_gen;

namespace {

constexpr uint64_t kCompMask = (uint64_t{1} << fmts::kUnitComp.width()) - 1;
constexpr int32_t kCompMax = static_cast<int32_t>(fmts::kUnitComp.max_raw());
constexpr int32_t kCompMin = static_cast<int32_t>(fmts::kUnitComp.min_raw());
constexpr int32_t kOne = 1 << fmts::kUnitComp.frac_bits;
// Random items: a reload of every table from a new frame in the middle of every this many.
constexpr size_t kReloadPeriod = 16384;

int32_t limit(const TableConfig& c) { return (1 << (c.value_bits - 1)) - 1; }
uint32_t entries(const TableConfig& c) { return 10 * c.grid.quarter(); }  // 3 x 2Q + 4 x Q
// |uN| with every entry it reads at the limit: (lim^2 + lim 2^(W-1)) 2^-(2W-2), in SQ2.14.
int32_t largest_dot(const TableConfig& c) {
  const int64_t lim = limit(c);
  const int shift = 2 * c.value_bits - 2 - fmts::kUnitComp.frac_bits;
  const int64_t sum = lim * lim + (lim << (c.value_bits - 1));
  return static_cast<int32_t>(shift == 0 ? sum : (sum + (int64_t{1} << (shift - 1))) >> shift);
}

bool is_write(const Txn& t) { return t.f[0] == D::op_tw; }
deflect::TableWrite table_write(const Txn& t) {
  return {static_cast<uint8_t>(t.f[D::tw_table]), static_cast<uint32_t>(t.f[D::tw_addr]),
          static_cast<int32_t>(t.f[D::tw_value])};  // raw port bits: the memory takes the low W
}
SphereAngle request_angle(const Txn& t) {
  return {static_cast<uint32_t>(t.f[D::in_phi]), static_cast<uint32_t>(t.f[D::in_theta])};
}

Txn output_txn(const MapCoords& c) {
  Txn t;
  t.f[D::out_un] = static_cast<uint64_t>(c.un) & kCompMask;
  t.f[D::out_vn] = static_cast<uint64_t>(c.vn) & kCompMask;
  t.f[D::out_ur] = static_cast<uint64_t>(c.ur) & kCompMask;
  t.f[D::out_vr] = static_cast<uint64_t>(c.vr) & kCompMask;
  t.f[D::out_wr] = static_cast<uint64_t>(c.wr) & kCompMask;
  return t;
}
int32_t comp(const Txn& out, int field) {
  const auto raw = static_cast<int32_t>(out.f[static_cast<size_t>(field)]);
  return raw > kCompMax ? raw - (kCompMax - kCompMin + 1) : raw;
}

// The tables as the port loaded them: a request is evaluated on the writes before it.
class Golden : public Model {
 public:
  explicit Golden(const TableConfig& config) : tables_(config) {}
  void step(const Txn& item, Sink& sink) override {
    if (is_write(item)) {
      tables_.write(table_write(item));
    } else {
      sink.output(output_txn(tables_.eval(request_angle(item))));
    }
  }

 private:
  deflect::CoordTableMemory tables_;
};

std::string tables_options(const TableConfig& c) {
  return fmt::format("--coord-tables {},{}", c.grid.phi_bits, c.value_bits);
}

// A unit vector uniformly on the sphere from two draws in [0, 1).
std::array<double, 3> unit_vector(double a, double b) {
  const double z = 2.0 * a - 1.0;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * std::numbers::pi * b;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
double draw_unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// The named angles of the directed sweep: phi at the phi tables' ends and their negated copy,
// theta at +-0 (and the -0 input), +-1, +-Q/2 and the poles +-(Q-1).
std::vector<Txn> angle_sweep(const TableConfig& c) {
  const deflect::SphereGrid& g = c.grid;
  const uint32_t q = g.quarter();
  const uint32_t minus_zero = 1u << g.mag_bits();  // sign bit alone
  std::vector<Txn> items;
  for (uint32_t phi : {0u, 1u, q - 1, q, 2 * q - 1, 2 * q, 2 * q + 1, 3 * q, 4 * q - 1}) {
    for (uint32_t mag : {0u, 1u, q / 2, q - 1}) {
      items.push_back(coord_request_item(phi, deflect::make_theta(g, false, mag)));
      items.push_back(
          coord_request_item(phi, mag == 0 ? minus_zero : deflect::make_theta(g, true, mag)));
    }
  }
  return items;
}

// Every entry of every table written through the port with value_of(table).
template <class F>
void fill_tables(const TableConfig& c, std::vector<Txn>& items, F value_of) {
  for (int t = 0; t < deflect::kCoordTableCount; ++t) {
    const auto table = static_cast<CoordTable>(t);
    for (uint32_t a = 0; a < deflect::coord_table_size(c.grid, table); ++a) {
      items.push_back(coord_write_item(static_cast<uint8_t>(t), a, value_of(table)));
    }
  }
}

void append(std::vector<Txn>& to, const std::vector<Txn>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

Txn coord_write_item(uint8_t table, uint32_t address, int32_t value) {
  return channel_item(D::table(), "tw", {table, address, static_cast<uint32_t>(value)});
}

Txn coord_request_item(uint32_t phi, uint32_t theta) {
  return channel_item(D::table(), "in", {phi, theta});
}

std::vector<Txn> coord_load_items(const CoordTables& tables) {
  std::vector<Txn> items;
  for (const deflect::TableWrite& w : tables.writes()) {
    items.push_back(coord_write_item(w.table, w.address, w.value));
  }
  return items;
}

ViewFrame random_view_frame(std::mt19937_64& rng) {
  ViewFrame f;
  f.side = unit_vector(draw_unit(rng), draw_unit(rng));
  // up: a second random direction made orthogonal to side (Gram-Schmidt); a draw too close
  // to +-side is drawn again.
  while (true) {
    const auto r = unit_vector(draw_unit(rng), draw_unit(rng));
    const double d = r[0] * f.side[0] + r[1] * f.side[1] + r[2] * f.side[2];
    std::array<double, 3> up{r[0] - d * f.side[0], r[1] - d * f.side[1], r[2] - d * f.side[2]};
    const double n = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    if (n < 1e-3) continue;
    for (double& x : up) x /= n;
    f.up = up;
    break;
  }
  const auto& s = f.side;
  const auto& u = f.up;
  f.dir = {s[1] * u[2] - s[2] * u[1], s[2] * u[0] - s[0] * u[2], s[0] * u[1] - s[1] * u[0]};
  return f;
}

CoordGenBlock::CoordGenBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), seed_(options.seed), config_(options.coord_tables) {
  const TableConfig& c = config_;
  if (c.grid.phi_bits < 6 || c.grid.phi_bits > fmts::kSpherePhi.width() || c.value_bits < 8 ||
      c.value_bits > fmts::kCoordValue.width()) {
    throw std::invalid_argument(fmt::format(
        "coord_gen: tables of grid A = {} and W = {} bits (the ports take A 6..{}, W 8..{})",
        c.grid.phi_bits, c.value_bits, fmts::kSpherePhi.width(), fmts::kCoordValue.width()));
  }
  add_level("hls", hls_level<desc::coord_gen_sc, hls::CoordGenSc>(config_));
  TMU_ADD_RTL_LEVELS(coord_gen, variant());
  // Tables no variant verilates have no rtl level (texsim cosim notes it); Icarus runs them
  // with the grid and width as the RTL's parameters.
  const std::vector<std::string> have = levels();
  if (std::find(have.begin(), have.end(), "rtl") == have.end()) {
    add_level("icarus", icarus_level("tmu_coord_gen", fmt::format("PhiBits={} ValueBits={}",
                                                                  c.grid.phi_bits, c.value_bits)));
  }
}

std::string CoordGenBlock::variant() const {
  return config_ == TableConfig{}
             ? ""
             : fmt::format("a{}w{}", config_.grid.phi_bits, config_.value_bits);
}

std::string CoordGenBlock::repro_options() const {
  return config_ == TableConfig{} ? "" : tables_options(config_);
}

std::unique_ptr<Model> CoordGenBlock::golden() const { return std::make_unique<Golden>(config_); }

std::vector<Txn> CoordGenBlock::setup_items() const {
  // Every entry (the tables have no reset), from the seed's view frame.
  std::mt19937_64 rng(seed_ ^ 0xC06Du);
  return coord_load_items(CoordTables(config_, random_view_frame(rng)));
}

std::vector<Txn> CoordGenBlock::directed_items() const {
  const TableConfig& c = config_;
  const deflect::SphereGrid& g = c.grid;
  const uint32_t q = g.quarter();
  const int32_t lim = limit(c);
  std::vector<Txn> items;

  // The angle corners on the seed's frame (loaded by the setup).
  append(items, angle_sweep(c));

  // A write followed at once by a request reading that entry, every table, then the entry
  // rewritten and read through its negated copy (phi + pi, or theta < 0); then a request
  // followed at once by a write of an entry it reads (the request must not see it) and the
  // same request again.
  const uint32_t phi_at = q + q / 2, theta_at = q / 4, theta_other = q / 8 + 1;
  for (int t = 0; t < deflect::kCoordTableCount; ++t) {
    const auto table = static_cast<CoordTable>(t);
    const auto id = static_cast<uint8_t>(t);
    const auto k = static_cast<uint32_t>(t);
    const int32_t v1 = lim * (4 - t) / 5, v2 = -lim * (3 + t) / 10, v3 = lim * (t - 2) / 7;
    const bool phi_table = deflect::is_phi_table(table);
    const uint32_t p = phi_table ? phi_at + k : 3 * q + 5;
    const uint32_t m = phi_table ? theta_other : theta_at + k;
    const uint32_t addr = phi_table ? p : m;
    items.push_back(coord_write_item(id, addr, v1));
    items.push_back(coord_request_item(p, deflect::make_theta(g, false, m)));
    items.push_back(coord_write_item(id, addr, v2));
    items.push_back(coord_request_item(phi_table ? p + 2 * q : 5, deflect::make_theta(g, true, m)));
    items.push_back(coord_request_item(p, deflect::make_theta(g, true, m)));
    items.push_back(coord_write_item(id, addr, v3));
    items.push_back(coord_request_item(p, deflect::make_theta(g, true, m)));
  }
  // Back-to-back writes to three tables, one request reading all three.
  const uint32_t m2 = q / 8 + 4, p2 = 3 * q / 4 + 4;
  items.push_back(coord_write_item(deflect::kF1, m2, lim * 3 / 5));
  items.push_back(coord_write_item(deflect::kH2, p2, -lim * 4 / 5));
  items.push_back(coord_write_item(deflect::kH3, m2, lim / 2));
  items.push_back(coord_request_item(p2, deflect::make_theta(g, false, m2)));

  // The port's rules: -2^(W-1) is stored as the limit (read as is and negated); writes to
  // table 7 or beyond a theta table's Q entries change nothing.
  items.push_back(coord_write_item(deflect::kF2, 5, -lim - 1));
  items.push_back(coord_request_item(5, deflect::make_theta(g, false, 0)));
  items.push_back(coord_request_item(2 * q + 5, 1u << g.mag_bits()));
  items.push_back(coord_write_item(deflect::kF3, q + 3, 77));
  items.push_back(coord_request_item(0, deflect::make_theta(g, true, 3)));
  items.push_back(coord_write_item(7, 3, 123));
  items.push_back(coord_request_item(0, deflect::make_theta(g, false, 3)));

  // View changes in the middle of the stream: frames with components of exactly +-1, whose
  // entries reach +-(2^(W-1) - 1) (e.g. H2(0) = cos 0 = 1 saturated; the mirrored frame's
  // F2(Q) = -1 and G3(Q-1) ~ -1).
  append(items, coord_load_items(CoordTables(c, ViewFrame{})));
  append(items, angle_sweep(c));
  ViewFrame mirrored;
  mirrored.side = {-1, 0, 0};
  mirrored.up = {0, -1, 0};
  mirrored.dir = {0, 0, 1};  // side x up
  append(items, coord_load_items(CoordTables(c, mirrored)));
  append(items, angle_sweep(c));

  // Tables filled through explicit writes with the limit and 0. Every entry +limit: uN, vN,
  // hN reach +-32672 (1.994), so 2 hN uN reaches 7.95: uR, vR, wR saturate high. H2, H3 at
  // -limit instead: hN and uN of opposite signs, uR, vR saturate low. All 0: wR = -1.
  fill_tables(c, items, [lim](CoordTable) { return lim; });
  append(items, angle_sweep(c));
  fill_tables(c, items,
              [lim](CoordTable t) { return t == deflect::kH2 || t == deflect::kH3 ? -lim : lim; });
  append(items, angle_sweep(c));
  fill_tables(c, items, [](CoordTable) { return 0; });
  append(items, angle_sweep(c));

  // The seed's frame again for the random items.
  append(items, setup_items());
  append(items, angle_sweep(c));
  return items;
}

std::vector<Txn> CoordGenBlock::random_items(std::mt19937_64& rng, size_t count) const {
  const TableConfig& c = config_;
  std::vector<Txn> items;
  items.reserve(count);
  size_t next_reload = kReloadPeriod / 2;
  while (items.size() < count) {
    if (items.size() >= next_reload) {  // a view change: every table from a new frame
      next_reload += kReloadPeriod;
      if (items.size() + entries(c) <= count) {
        append(items, coord_load_items(CoordTables(c, random_view_frame(rng))));
        continue;
      }
    }
    const uint64_t r = rng();
    if ((r & 63) == 0) {  // one item in 64 rewrites an entry (table 7 or beyond: ignored)
      items.push_back(coord_write_item(static_cast<uint8_t>(r >> 8), static_cast<uint32_t>(r >> 16),
                                       static_cast<int32_t>(r >> 32)));
    } else {
      items.push_back(coord_request_item(static_cast<uint32_t>(r >> 8) & c.grid.phi_mask(),
                                         static_cast<uint32_t>(r >> 24)));
    }
  }
  return items;
}

std::vector<std::string> CoordGenBlock::coverage_cases() const {
  return {"theta +0",
          "theta -0 (input)",
          "theta +(Q-1) (pole)",
          "theta -(Q-1) (pole)",
          "phi 0",
          "phi Q (90 degrees)",
          "phi 2Q-1 (last entry)",
          "phi 2Q (first negated entry)",
          "phi 4Q-1 (last negated entry)",
          "entry +(2^(W-1)-1) read",
          "entry -(2^(W-1)-1) read",
          "request right after a write",
          "request reads the entry just written",
          "entry rewritten right after its read",
          "request after a reload (view change)",
          "-2^(W-1) written (stored as limit)",
          "write beyond the tables (ignored)",
          "|uN| or |vN| at its largest",
          "uR saturated high",
          "uR saturated low",
          "vR saturated high",
          "vR saturated low",
          "wR saturated high",
          "wR = -1 (hN = 0)"};
}

void CoordGenBlock::cover(const std::vector<Txn>& items, size_t index, const Txn& output,
                          Coverage& cov) const {
  const TableConfig& c = config_;
  const deflect::SphereGrid& g = c.grid;
  const uint32_t q = g.quarter();
  const int32_t lim = limit(c);
  CoverState& st = cover_state_;
  if (st.items != &items || index < st.next || !st.tables) {
    st = CoverState{&items, 0, std::make_shared<deflect::CoordTableMemory>(c)};
  }
  for (; st.next < index; ++st.next) {
    const Txn& t = items[st.next];
    if (!is_write(t)) {
      st.writes_since_request = 0;
      st.min_value_written = st.ignored_write = false;
      continue;
    }
    ++st.writes_since_request;
    const deflect::TableWrite w = table_write(t);
    const auto min_bits = uint32_t{1} << (c.value_bits - 1);  // -2^(W-1) in W bits
    if (!st.tables->write(w)) {
      st.ignored_write = true;
    } else if ((static_cast<uint32_t>(w.value) & (2 * min_bits - 1)) == min_bits) {
      st.min_value_written = true;
    }
  }

  const SphereAngle a = request_angle(items[index]);
  const uint32_t mag = deflect::theta_mag(g, a.theta);
  const bool neg = deflect::theta_negative(g, a.theta);
  const uint32_t phi = a.phi & g.phi_mask();
  const uint32_t pi = phi % (2 * q);
  if (mag == 0) ++cov[neg ? "theta -0 (input)" : "theta +0"];
  if (mag == q - 1) ++cov[neg ? "theta -(Q-1) (pole)" : "theta +(Q-1) (pole)"];
  if (phi == 0) ++cov["phi 0"];
  if (phi == q) ++cov["phi Q (90 degrees)"];
  if (phi == 2 * q - 1) ++cov["phi 2Q-1 (last entry)"];
  if (phi == 2 * q) ++cov["phi 2Q (first negated entry)"];
  if (phi == 4 * q - 1) ++cov["phi 4Q-1 (last negated entry)"];

  bool at_max = false, at_min = false;
  for (int t = 0; t < deflect::kCoordTableCount; ++t) {
    const auto table = static_cast<CoordTable>(t);
    const int32_t e = st.tables->entry(table, deflect::is_phi_table(table) ? pi : mag);
    at_max |= e == lim;
    at_min |= e == -lim;
  }
  if (at_max) ++cov["entry +(2^(W-1)-1) read"];
  if (at_min) ++cov["entry -(2^(W-1)-1) read"];
  if (index > 0 && is_write(items[index - 1])) {
    ++cov["request right after a write"];
    const deflect::TableWrite w = table_write(items[index - 1]);
    if (w.table < deflect::kCoordTableCount) {
      const auto table = static_cast<CoordTable>(w.table);
      if (w.address == (deflect::is_phi_table(table) ? pi : mag)) {
        ++cov["request reads the entry just written"];
      }
    }
  }
  if (index + 1 < items.size() && is_write(items[index + 1])) {
    const deflect::TableWrite w = table_write(items[index + 1]);
    if (w.table < deflect::kCoordTableCount) {
      const auto table = static_cast<CoordTable>(w.table);
      if (w.address == (deflect::is_phi_table(table) ? pi : mag)) {
        ++cov["entry rewritten right after its read"];
      }
    }
  }
  if (st.writes_since_request >= entries(c)) ++cov["request after a reload (view change)"];
  if (st.min_value_written) ++cov["-2^(W-1) written (stored as limit)"];
  if (st.ignored_write) ++cov["write beyond the tables (ignored)"];

  const int32_t un = comp(output, D::out_un), vn = comp(output, D::out_vn);
  const int32_t ur = comp(output, D::out_ur), vr = comp(output, D::out_vr);
  const int32_t wr = comp(output, D::out_wr);
  // Only tables with every entry read at the limit give it (a frame's normal has length 1).
  if (std::max(std::abs(un), std::abs(vn)) == largest_dot(c)) ++cov["|uN| or |vN| at its largest"];
  if (ur == kCompMax) ++cov["uR saturated high"];
  if (ur == kCompMin) ++cov["uR saturated low"];
  if (vr == kCompMax) ++cov["vR saturated high"];
  if (vr == kCompMin) ++cov["vR saturated low"];
  if (wr == kCompMax) ++cov["wR saturated high"];
  if (wr == -kOne) ++cov["wR = -1 (hN = 0)"];
}

MapCoords coord_gen_output(const Txn& output) {
  return {comp(output, D::out_un), comp(output, D::out_vn), comp(output, D::out_ur),
          comp(output, D::out_vr), comp(output, D::out_wr)};
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(coord_gen, CoordGenBlock)
