#include "blocks/tau/tau_block.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/tau/tau_sc.hpp"
#include "rtl_models_tau.hpp"

TMU_DESCRIBE_SC(tau)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::tau;
using tau::Interp;

namespace {

constexpr int kFrac = fmts::kPcCoord.frac_bits;  // 16: one cell
constexpr int32_t kCell = int32_t{1} << kFrac;
constexpr int32_t kPcMin = static_cast<int32_t>(fmts::kPcCoord.min_raw());
constexpr int32_t kPcMax = static_cast<int32_t>(fmts::kPcCoord.max_raw());
constexpr int32_t kNodeMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kNodeMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr int32_t kTexel = int32_t{1} << fmts::kTexCoord.frac_bits;  // 256
// A random run draws a new grid after this many items.
constexpr size_t kBatch = 2000;

uint64_t bits(int32_t raw, const fx::Format& f) {
  return static_cast<uint64_t>(static_cast<uint32_t>(raw)) & ((uint64_t{1} << f.width()) - 1);
}

int32_t signed_field(uint64_t field, const fx::Format& f) {
  return static_cast<int32_t>(fx::fit(
      static_cast<int64_t>(field & ((uint64_t{1} << f.width()) - 1)), f, fx::Overflow::kWrap));
}

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions: the
// same stimulus on every standard library).
int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

int32_t clamp_node(double texels) {
  return static_cast<int32_t>(
      std::clamp<int64_t>(std::llround(texels * kTexel), kNodeMin, kNodeMax));
}

uint32_t node_addr(int i, int j) { return static_cast<uint32_t>(i + tau::kStride * j); }

// The golden unit over a run: configurations, node writes and samples in order.
class Golden : public Model {
 public:
  void configure(const Txn& cfg) override {
    tau::Config c;
    c.cells_s = static_cast<int>(cfg.f[D::cfg_cells_s]);
    c.cells_t = static_cast<int>(cfg.f[D::cfg_cells_t]);
    c.interp = cfg.f[D::cfg_interp] != 0 ? Interp::kSpline : Interp::kLinear;
    unit_.configure(c);
  }
  void step(const Txn& item, Sink& sink) override {
    if (item.f[0] == D::op_node) {
      unit_.write(static_cast<uint32_t>(item.f[D::node_addr]),
                  signed_field(item.f[D::node_u], fmts::kTexCoord),
                  signed_field(item.f[D::node_v], fmts::kTexCoord));
      return;
    }
    const tau::Result r = unit_.sample(tau_request_of(item));
    Txn out;
    out.f[D::out_u] = bits(r.u, fmts::kTexCoord);
    out.f[D::out_v] = bits(r.v, fmts::kTexCoord);
    out.f[D::out_r1u] = bits(r.r1u, fmts::kTexDeriv);
    out.f[D::out_r1v] = bits(r.r1v, fmts::kTexDeriv);
    out.f[D::out_r2u] = bits(r.r2u, fmts::kTexDeriv);
    out.f[D::out_r2v] = bits(r.r2v, fmts::kTexDeriv);
    out.f[D::out_lambda] = bits(r.lambda, fmts::kLod);
    sink.output(out);
  }

 private:
  tau::TauUnit unit_;
};

// A fragment's derivatives: zero, tiny, what a rasterizer gives (a cell over some 2..200
// pixels), or anything in PcDeriv.
int32_t draw_deriv(std::mt19937_64& rng) {
  const uint64_t r = rng() % 16;
  int64_t m = 0;
  if (r == 0) return 0;
  if (r == 1)
    m = uniform(rng, 1, 255);
  else if (r == 2)
    m = uniform(rng, 0, int64_t{kPcMax});
  else
    m = uniform(rng, kCell / 200, kCell / 2);
  return static_cast<int32_t>(rng() % 2 ? -m : m);
}

// A coordinate of a sample along an axis of `cells`: mostly inside, some on node lines, at
// the grid's ends and beyond them, now and then anywhere in PcCoord.
int32_t draw_coord(std::mt19937_64& rng, int cells) {
  const uint64_t r = rng() % 32;
  if (r == 0) return static_cast<int32_t>(uniform(rng, kPcMin, kPcMax));
  if (r < 3) return static_cast<int32_t>(uniform(rng, 0, cells) * kCell);  // a node line
  if (r < 5) return static_cast<int32_t>(uniform(rng, -kCell, 0));         // below the grid
  if (r < 7)
    return static_cast<int32_t>(uniform(rng, int64_t{cells} * kCell, (cells + 1) * int64_t{kCell}));
  return static_cast<int32_t>(uniform(rng, 0, int64_t{cells} * kCell));
}

TauGridKind draw_kind(std::mt19937_64& rng) {
  const uint64_t r = rng() % 10;
  if (r < 3) return TauGridKind::kSmooth;
  if (r < 5) return TauGridKind::kRandom;
  if (r < 7) return TauGridKind::kAffine;
  if (r < 9) return TauGridKind::kFolded;
  return TauGridKind::kExtreme;
}

int draw_cells(std::mt19937_64& rng) {
  const uint64_t r = rng() % 8;
  if (r == 0) return 1;
  if (r == 1) return tau::kMaxCells;
  return static_cast<int>(uniform(rng, 1, tau::kMaxCells));
}

// Coverage: the trace of a sample under the configuration in effect.
constexpr const char* kLinear = "linear (claim 5)";
constexpr const char* kSpline = "Catmull-Rom (claim 6)";
constexpr const char* kCells1 = "cells 1 along s or t";
constexpr const char* kCells16 = "cells 16 along s or t";
constexpr const char* kCellsOdd = "cells not a power of two";
constexpr const char* kNodeLine = "s or t on a node line inside (x = 0)";
constexpr const char* kAtCells = "s or t exactly at cells (x = 2^12)";
constexpr const char* kBelow = "s or t below the grid (clamped to 0)";
constexpr const char* kBeyond = "s or t beyond the grid (clamped to cells)";
constexpr const char* kExtrapolated = "a node extrapolated (spline at an edge)";
constexpr const char* kCorner = "a corner extrapolated along both axes";
constexpr const char* kZeroDeriv = "r1 = r2 = 0 (the smallest lambda)";
constexpr const char* kRSaturated = "r saturated";
constexpr const char* kUvSaturated = "u or v saturated";
constexpr const char* kFolded = "Jacobian determinant < 0 (a folded map)";
constexpr const char* kPositiveLambda = "lambda > 0 (minification)";
constexpr const char* kNegativeLambda = "lambda < 0 (magnification)";
constexpr const char* kAfterWrite = "sample right after a node write";
constexpr const char* kCellsClamped = "configured cells 0 or above 16";

}  // namespace

// ---- Items --------------------------------------------------------------------------------

Txn tau_config_item(const tau::Config& c) {
  return channel_item(D::table(), "cfg",
                      {static_cast<uint64_t>(c.cells_s) & 31, static_cast<uint64_t>(c.cells_t) & 31,
                       c.interp == Interp::kSpline ? 1u : 0u});
}

Txn tau_node_item(uint32_t addr, int32_t u, int32_t v) {
  return channel_item(D::table(), "node",
                      {addr, bits(u, fmts::kTexCoord), bits(v, fmts::kTexCoord)});
}

Txn tau_sample_item(const tau::Request& r) {
  const fx::Format c = fmts::kPcCoord, d = fmts::kPcDeriv;
  return channel_item(D::table(), "in",
                      {bits(r.s, c), bits(r.t, c), bits(r.ds_dx, d), bits(r.dt_dx, d),
                       bits(r.ds_dy, d), bits(r.dt_dy, d)});
}

std::vector<Txn> tau_load_items(const TauGrid& g) {
  std::vector<Txn> items = {tau_config_item(g.config)};
  const int cs = tau::effective_cells(g.config.cells_s),
            ct = tau::effective_cells(g.config.cells_t);
  for (int j = 0; j <= ct; ++j) {
    for (int i = 0; i <= cs; ++i) {
      const auto n = static_cast<size_t>(i + (cs + 1) * j);
      items.push_back(tau_node_item(node_addr(i, j), g.u[n], g.v[n]));
    }
  }
  return items;
}

tau::Request tau_request_of(const Txn& t) {
  const fx::Format c = fmts::kPcCoord, d = fmts::kPcDeriv;
  return {signed_field(t.f[D::in_s], c),     signed_field(t.f[D::in_t], c),
          signed_field(t.f[D::in_ds_dx], d), signed_field(t.f[D::in_dt_dx], d),
          signed_field(t.f[D::in_ds_dy], d), signed_field(t.f[D::in_dt_dy], d)};
}

tau::Result tau_result_of(const Txn& o) {
  const fx::Format c = fmts::kTexCoord, d = fmts::kTexDeriv;
  return {signed_field(o.f[D::out_u], c),
          signed_field(o.f[D::out_v], c),
          signed_field(o.f[D::out_r1u], d),
          signed_field(o.f[D::out_r1v], d),
          signed_field(o.f[D::out_r2u], d),
          signed_field(o.f[D::out_r2v], d),
          signed_field(o.f[D::out_lambda], fmts::kLod)};
}

TauGrid draw_tau_grid(std::mt19937_64& rng, TauGridKind kind, int cells_s, int cells_t,
                      Interp interp) {
  TauGrid g;
  g.config = {cells_s, cells_t, interp};
  const int cs = tau::effective_cells(cells_s), ct = tau::effective_cells(cells_t);
  const size_t n = static_cast<size_t>(cs + 1) * static_cast<size_t>(ct + 1);
  g.u.resize(n);
  g.v.resize(n);
  // Texels per cell: a texture of 16..1024 texels over the grid.
  const double span_u = static_cast<double>(uniform(rng, 16, 1024)) / cs;
  const double span_v = static_cast<double>(uniform(rng, 16, 1024)) / ct;
  const double shear = static_cast<double>(uniform(rng, -100, 100)) / 400;
  const double amp = static_cast<double>(uniform(rng, 0, 100)) / 200;
  const double ph = static_cast<double>(uniform(rng, 0, 628)) / 100;
  const int64_t u0 = uniform(rng, -64 * kTexel, 64 * kTexel),
                v0 = uniform(rng, -64 * kTexel, 64 * kTexel);
  const auto du = static_cast<int64_t>(span_u * kTexel) + uniform(rng, -255, 255);
  const auto dv = static_cast<int64_t>(span_v * kTexel) + uniform(rng, -255, 255);
  const auto duv = static_cast<int64_t>(shear * span_u * kTexel);
  const double fold =
      static_cast<double>(uniform(rng, 0, cs * 4)) / 4.0;  // where s's direction reverses
  for (int j = 0; j <= ct; ++j) {
    for (int i = 0; i <= cs; ++i) {
      const auto k = static_cast<size_t>(i + (cs + 1) * j);
      switch (kind) {
        case TauGridKind::kAffine:  // integer steps: exactly affine
          g.u[k] =
              static_cast<int32_t>(std::clamp<int64_t>(u0 + i * du + j * duv, kNodeMin, kNodeMax));
          g.v[k] = static_cast<int32_t>(
              std::clamp<int64_t>(v0 - i * duv / 2 + j * dv, kNodeMin, kNodeMax));
          break;
        case TauGridKind::kSmooth:
          g.u[k] = clamp_node(static_cast<double>(u0) / kTexel +
                              span_u * (i + amp * std::sin(0.9 * j + ph)) + shear * span_u * j);
          g.v[k] = clamp_node(static_cast<double>(v0) / kTexel +
                              span_v * (j + amp * std::sin(1.3 * i - ph)));
          break;
        case TauGridKind::kFolded:  // u runs back over itself past s = fold
          g.u[k] = clamp_node(static_cast<double>(u0) / kTexel +
                              span_u * (fold - std::abs(i - fold)) + shear * span_u * j);
          g.v[k] = clamp_node(static_cast<double>(v0) / kTexel + span_v * j + amp * span_v * i);
          break;
        case TauGridKind::kRandom:
          g.u[k] = static_cast<int32_t>(uniform(rng, -(int64_t{1} << 20), int64_t{1} << 20));
          g.v[k] = static_cast<int32_t>(uniform(rng, -(int64_t{1} << 20), int64_t{1} << 20));
          break;
        case TauGridKind::kExtreme: {
          const std::array<int32_t, 4> ends = {kNodeMin, kNodeMax, 0, kNodeMax - 1};
          g.u[k] = ends[rng() % 4];
          g.v[k] = ends[rng() % 4];
          break;
        }
      }
    }
  }
  return g;
}

// ---- The block ----------------------------------------------------------------------------

TauBlock::TauBlock(const BlockOptions& options) : DescribedBlockOf(D::table()) {
  std::mt19937_64 rng(options.seed ^ 0x7A0'0000'0001ull);
  first_ = draw_tau_grid(rng, TauGridKind::kSmooth, 3, 2, Interp::kSpline);
  add_level("hls", hls_level<desc::tau_sc, hls::TauSc>());
  TMU_ADD_RTL_LEVELS(tau, variant());
}

std::vector<Txn> TauBlock::setup_items() const { return tau_load_items(first_); }

std::vector<Txn> TauBlock::directed_items() const {
  std::vector<Txn> items;
  std::mt19937_64 rng(0x7A0D);
  const auto sample = [&items](int32_t s, int32_t t, int32_t a = kCell / 64, int32_t b = 0,
                               int32_t c = 0, int32_t d = kCell / 64) {
    items.push_back(tau_sample_item({s, t, a, b, c, d}));
  };
  // Every place along the grid that the weights, the fold or the clamp treat apart.
  const auto walk = [&](int cs, int ct) {
    const int32_t S = cs * kCell, T = ct * kCell;
    for (int32_t s : {0, S, S / 2, kCell, S - 1, 1}) {
      for (int32_t t : {0, T, T / 2, kCell, T - 1}) sample(s, t);
    }
    for (int i = 0; i <= cs; ++i) sample(i * kCell, (ct * kCell) / 3);      // node lines
    for (int i = 0; i < cs; ++i) sample(i * kCell + kCell / 2, kCell / 3);  // cell centres
    sample(-1, -1);                                                         // just below
    sample(S + 1, T + 1);                                                   // just beyond
    sample(-kCell / 2, T / 2);
    sample(S / 2, T + kCell / 2);
    sample(kPcMin, kPcMax);
    sample(kPcMax, kPcMin);
    sample(S / 3, T / 3, 0, 0, 0, 0);                      // zero derivatives
    sample(S / 3, T / 3, kPcMax, kPcMax, kPcMin, kPcMax);  // r saturates
    sample(S / 3, T / 3, 1, 0, 0, -1);                     // the smallest derivatives
    sample(S / 5, T / 7, kCell, -kCell / 3, kCell / 5, kCell / 2);
  };
  const auto grid = [&](TauGridKind kind, int cs, int ct, Interp interp) {
    for (const Txn& t : tau_load_items(draw_tau_grid(rng, kind, cs, ct, interp)))
      items.push_back(t);
    walk(tau::effective_cells(cs), tau::effective_cells(ct));
  };
  for (const Interp interp : {Interp::kLinear, Interp::kSpline}) {
    grid(TauGridKind::kSmooth, 1, 1, interp);
    grid(TauGridKind::kAffine, 16, 16, interp);
    grid(TauGridKind::kSmooth, 3, 5, interp);
    grid(TauGridKind::kFolded, 7, 2, interp);
    grid(TauGridKind::kExtreme, 2, 3, interp);
    grid(TauGridKind::kRandom, 5, 1, interp);
    grid(TauGridKind::kAffine, 0, 31, interp);  // cells 0 acts as 1, 31 as 16
  }
  // Writes interleaved with samples: a node rewritten between two samples that read it, a
  // write right after a sample (it must not reach that sample), back-to-back writes.
  const TauGrid g = draw_tau_grid(rng, TauGridKind::kSmooth, 2, 2, Interp::kSpline);
  for (const Txn& t : tau_load_items(g)) items.push_back(t);
  const int32_t s = kCell + kCell / 4, t = kCell - kCell / 8;
  sample(s, t);
  items.push_back(tau_node_item(node_addr(1, 1), 100 * kTexel, -50 * kTexel));
  sample(s, t);
  items.push_back(tau_node_item(node_addr(1, 1), g.u[4], g.v[4]));
  items.push_back(tau_node_item(node_addr(2, 1), kNodeMax, kNodeMin));
  items.push_back(tau_node_item(node_addr(2, 1), g.u[5], g.v[5]));
  sample(s, t);
  items.push_back(tau_node_item(300, 1, 1));  // beyond the memory: dropped
  items.push_back(tau_node_item(511, 2, 2));
  sample(s, t);
  // Back to the first grid, where the random items begin.
  for (const Txn& x : tau_load_items(first_)) items.push_back(x);
  return items;
}

std::vector<Txn> TauBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  int cs = tau::effective_cells(first_.config.cells_s),
      ct = tau::effective_cells(first_.config.cells_t);
  size_t next_batch = kBatch;
  while (items.size() < count) {
    if (items.size() >= next_batch) {  // a new grid, as a driver between batches
      next_batch += kBatch;
      const Interp interp = rng() % 2 ? Interp::kSpline : Interp::kLinear;
      const TauGrid g =
          draw_tau_grid(rng, draw_kind(rng), draw_cells(rng), draw_cells(rng), interp);
      for (const Txn& t : tau_load_items(g)) items.push_back(t);
      cs = g.config.cells_s;
      ct = g.config.cells_t;
      continue;
    }
    if (rng() % 200 == 0) {  // now and then a node rewritten between samples
      const int i = static_cast<int>(uniform(rng, 0, cs)),
                j = static_cast<int>(uniform(rng, 0, ct));
      items.push_back(tau_node_item(node_addr(i, j),
                                    static_cast<int32_t>(uniform(rng, -(1 << 20), 1 << 20)),
                                    static_cast<int32_t>(uniform(rng, -(1 << 20), 1 << 20))));
      continue;
    }
    items.push_back(tau_sample_item({draw_coord(rng, cs), draw_coord(rng, ct), draw_deriv(rng),
                                     draw_deriv(rng), draw_deriv(rng), draw_deriv(rng)}));
  }
  return items;
}

std::unique_ptr<Model> TauBlock::golden() const { return std::make_unique<Golden>(); }

std::vector<std::string> TauBlock::coverage_cases() const {
  return {kLinear,         kSpline,         kCells1,     kCells16,     kCellsOdd,
          kNodeLine,       kAtCells,        kBelow,      kBeyond,      kExtrapolated,
          kCorner,         kZeroDeriv,      kRSaturated, kUvSaturated, kFolded,
          kPositiveLambda, kNegativeLambda, kAfterWrite, kCellsClamped};
}

void TauBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&, Coverage& cov) const {
  if (index < cover_next_) {  // a new run: replay from its start
    cover_next_ = 0;
    cover_unit_ = tau::TauUnit{};
  }
  bool clamped_cells = false;
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& x = items[cover_next_];
    if (x.f[0] == D::op_cfg) {
      tau::Config c;
      c.cells_s = static_cast<int>(x.f[D::cfg_cells_s]);
      c.cells_t = static_cast<int>(x.f[D::cfg_cells_t]);
      c.interp = x.f[D::cfg_interp] != 0 ? Interp::kSpline : Interp::kLinear;
      cover_unit_.configure(c);
      cover_clamped_ =
          c.cells_s != cover_unit_.config().cells_s || c.cells_t != cover_unit_.config().cells_t;
    } else if (x.f[0] == D::op_node) {
      cover_unit_.write(static_cast<uint32_t>(x.f[D::node_addr]),
                        signed_field(x.f[D::node_u], fmts::kTexCoord),
                        signed_field(x.f[D::node_v], fmts::kTexCoord));
    }
  }
  clamped_cells = cover_clamped_;
  cover_next_ = index + 1;
  const tau::Request r = tau_request_of(items[index]);
  const tau::Trace tr = cover_unit_.trace(r);
  const tau::Config& c = cover_unit_.config();
  ++cov[c.interp == Interp::kSpline ? kSpline : kLinear];
  if (c.cells_s == 1 || c.cells_t == 1) ++cov[kCells1];
  if (c.cells_s == 16 || c.cells_t == 16) ++cov[kCells16];
  if (!std::has_single_bit(static_cast<unsigned>(c.cells_s)) ||
      !std::has_single_bit(static_cast<unsigned>(c.cells_t)))
    ++cov[kCellsOdd];
  if (clamped_cells) ++cov[kCellsClamped];
  const auto axis = [&cov](int32_t coord, int cells, const tau::AxisWeights& a) {
    if (coord > 0 && coord < cells * kCell && a.x == 0) ++cov[kNodeLine];
    if (a.x == 4096) ++cov[kAtCells];
    if (coord < 0) ++cov[kBelow];
    if (coord > cells * kCell) ++cov[kBeyond];
  };
  axis(r.s, c.cells_s, tr.s);
  axis(r.t, c.cells_t, tr.t);
  if (tr.extrapolated) ++cov[kExtrapolated];
  const auto outside = [](const tau::AxisWeights& a, int cells) {
    return a.count == 4 && (a.first < 0 || a.first + 3 > cells);
  };
  if (outside(tr.s, c.cells_s) && outside(tr.t, c.cells_t)) ++cov[kCorner];
  const tau::Result& o = tr.result;
  if (o.r1u == 0 && o.r1v == 0 && o.r2u == 0 && o.r2v == 0) ++cov[kZeroDeriv];
  if (tr.r_saturated) ++cov[kRSaturated];
  if (tr.uv_saturated) ++cov[kUvSaturated];
  if (int64_t{tr.jus} * tr.jvt - int64_t{tr.jut} * tr.jvs < 0) ++cov[kFolded];
  if (o.lambda > 0) ++cov[kPositiveLambda];
  if (o.lambda < 0) ++cov[kNegativeLambda];
  if (index > 0 && items[index - 1].f[0] == D::op_node) ++cov[kAfterWrite];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(tau, TauBlock)
