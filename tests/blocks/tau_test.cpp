// What is the tau unit's own (004: EP0637814 claims 4-6, 15; the conformance suite,
// tests/conformance_test.cpp, checks what every block shares): golden against the ideal map
// within the error bounds derived in docs/tau.md, affine grids reproduced exactly by both
// interpolations, the linear mode's values on node lines, lambda as the footprint setup's
// log2 |r_max|, the write-ordering rule through every engine, and the cycles per sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include "blocks/tau/tau_block.hpp"
#include "footprint/footprint.hpp"
#include "tau/tau_ideal.hpp"
#include "tau/tau_unit.hpp"

namespace tmu::tb {
namespace {

using tau::Interp;
constexpr double kCell = 65536.0;  // raw PcCoord per cell
constexpr double kTexel = 256.0;   // raw TexCoord per texel

tau::TauUnit unit_of(const TauGrid& g) {
  tau::TauUnit unit;
  unit.configure(g.config);
  const int cs = tau::effective_cells(g.config.cells_s),
            ct = tau::effective_cells(g.config.cells_t);
  for (int j = 0; j <= ct; ++j) {
    for (int i = 0; i <= cs; ++i) {
      const auto k = static_cast<size_t>(i + (cs + 1) * j);
      unit.write(static_cast<uint32_t>(i + tau::kStride * j), g.u[k], g.v[k]);
    }
  }
  return unit;
}

tau::GridD ideal_grid(const TauGrid& g) {
  tau::GridD d;
  d.cells_s = tau::effective_cells(g.config.cells_s);
  d.cells_t = tau::effective_cells(g.config.cells_t);
  for (size_t k = 0; k < g.u.size(); ++k) {
    d.u.push_back(g.u[k] / kTexel);
    d.v.push_back(g.v[k] / kTexel);
  }
  return d;
}

// The range of a component over the sample's stencil (extrapolated nodes included), texels.
double stencil_range(const tau::TauUnit& unit, const tau::Trace& tr, bool v) {
  double lo = 1e300, hi = -1e300;
  for (int b = 0; b < tr.t.count; ++b) {
    for (int a = 0; a < tr.s.count; ++a) {
      const double n = static_cast<double>(unit.node(tr.s.first + a, tr.t.first + b, v)) / kTexel;
      lo = std::min(lo, n);
      hi = std::max(hi, n);
    }
  }
  return hi - lo;
}

struct Worst {
  double err = 0, ratio = 0;
  void add(double e, double bound) {
    err = std::max(err, e);
    ratio = std::max(ratio, e / bound);
  }
};

// Golden against the ideal on random grids and requests (docs/tau.md, "Accuracy", derives the
// bounds): per component, with R the component's range over the stencil in texels,
//   u:  2^-12 (|u_s| + |u_t|) + 2^-22 R   the 12-bit fraction truncated (< 2^-12 cell)
//       + 17.6 2^-13 R (spline only)       x2, x3 rounded: weight errors summing to zero
//       + 2^-9                              the final rounding to SQ16.8
//   J:  2^-12 K_T R + K_W 2^-13 R + 2^-11   (K_T = 12, K_W = 28.6 spline; K_T = 4, 0 linear)
//   r:  dJ_s |ds| + dJ_t |dt| + 2^-9
//   lambda: 1.1 dr / (|r| ln 2) + 0.0072    (r's error, then the log's: mantissa to 7 bits,
//                                            LOG rounding, 12-bit components, rounding to 8)
TEST(TauTest, GoldenAgainstIdeal) {
  std::mt19937_64 rng(11);
  const std::array<TauGridKind, 4> kinds = {TauGridKind::kSmooth, TauGridKind::kAffine,
                                            TauGridKind::kRandom, TauGridKind::kFolded};
  std::map<std::string, Worst> worst;
  int checked = 0, lambda_checked = 0;
  for (int g = 0; g < 80; ++g) {
    const Interp interp = g % 2 ? Interp::kSpline : Interp::kLinear;
    const TauGrid grid =
        draw_tau_grid(rng, kinds[static_cast<size_t>(g / 2) % kinds.size()],
                      1 + static_cast<int>(rng() % 16), 1 + static_cast<int>(rng() % 16), interp);
    const tau::TauUnit unit = unit_of(grid);
    const tau::GridD ideal = ideal_grid(grid);
    const double kw = interp == Interp::kSpline ? 17.6 : 0.0;
    const double jt = interp == Interp::kSpline ? 12.0 : 4.0,
                 jw = interp == Interp::kSpline ? 28.6 : 0.0;
    for (int n = 0; n < 2000; ++n) {
      tau::Request r;
      r.s =
          static_cast<int32_t>(rng() % static_cast<uint64_t>((ideal.cells_s + 1) * 65536)) - 32768;
      r.t =
          static_cast<int32_t>(rng() % static_cast<uint64_t>((ideal.cells_t + 1) * 65536)) - 32768;
      const auto deriv = [&rng] { return static_cast<int32_t>(rng() % 8192) - 4096; };
      r.ds_dx = deriv();
      r.dt_dx = deriv();
      r.ds_dy = deriv();
      r.dt_dy = deriv();
      const tau::Trace tr = unit.trace(r);
      if (tr.uv_saturated || tr.j_saturated || tr.r_saturated) continue;
      const tau::IdealResult id =
          tau::ideal_sample(ideal, interp, r.s / kCell, r.t / kCell, r.ds_dx / kCell,
                            r.dt_dx / kCell, r.ds_dy / kCell, r.dt_dy / kCell);
      const tau::MapD m = tau::ideal_map(ideal, interp, r.s / kCell, r.t / kCell);
      const double ru = stencil_range(unit, tr, false), rv = stencil_range(unit, tr, true);
      const double e12 = std::ldexp(1.0, -12), e13 = std::ldexp(1.0, -13);
      const double bu = e12 * (std::abs(m.du_ds) + std::abs(m.du_dt)) + std::ldexp(ru, -22) +
                        kw * e13 * ru + std::ldexp(1.0, -9) + 1e-9;
      const double bv = e12 * (std::abs(m.dv_ds) + std::abs(m.dv_dt)) + std::ldexp(rv, -22) +
                        kw * e13 * rv + std::ldexp(1.0, -9) + 1e-9;
      worst["u"].add(std::abs(tr.result.u / kTexel - id.u), bu);
      worst["v"].add(std::abs(tr.result.v / kTexel - id.v), bv);
      ASSERT_LE(std::abs(tr.result.u / kTexel - id.u), bu) << g << " " << n;
      ASSERT_LE(std::abs(tr.result.v / kTexel - id.v), bv) << g << " " << n;
      const double dju = e12 * jt * ru + jw * e13 * ru + std::ldexp(1.0, -11);
      const double djv = e12 * jt * rv + jw * e13 * rv + std::ldexp(1.0, -11);
      const double j_gold[4] = {tr.jus / 1024.0, tr.jut / 1024.0, tr.jvs / 1024.0, tr.jvt / 1024.0};
      const double j_ideal[4] = {m.du_ds, m.du_dt, m.dv_ds, m.dv_dt};
      for (int k = 0; k < 4; ++k) {
        const double b = (k < 2 ? dju : djv) + 1e-9;
        worst["J"].add(std::abs(j_gold[k] - j_ideal[k]), b);
        ASSERT_LE(std::abs(j_gold[k] - j_ideal[k]), b) << g << " " << n << " J" << k;
      }
      const double dsx = std::abs(r.ds_dx / kCell), dtx = std::abs(r.dt_dx / kCell);
      const double dsy = std::abs(r.ds_dy / kCell), dty = std::abs(r.dt_dy / kCell);
      const double half = std::ldexp(1.0, -9);
      const double b_r[4] = {dju * (dsx + dtx) + half, djv * (dsx + dtx) + half,
                             dju * (dsy + dty) + half, djv * (dsy + dty) + half};
      const double r_gold[4] = {tr.result.r1u / kTexel, tr.result.r1v / kTexel,
                                tr.result.r2u / kTexel, tr.result.r2v / kTexel};
      const double r_ideal[4] = {id.r1u, id.r1v, id.r2u, id.r2v};
      for (int k = 0; k < 4; ++k) {
        worst["r"].add(std::abs(r_gold[k] - r_ideal[k]), b_r[k] + 1e-9);
        ASSERT_LE(std::abs(r_gold[k] - r_ideal[k]), b_r[k] + 1e-9) << g << " " << n << " r" << k;
      }
      const double r_len = std::exp2(id.lambda);
      const double dr = std::sqrt(2.0) * std::max({b_r[0], b_r[1], b_r[2], b_r[3]});
      if (std::isfinite(id.lambda) && r_len > 4 * dr) {
        const double bl = 1.1 * dr / (r_len * std::log(2.0)) + 0.0072;
        worst["lambda"].add(std::abs(tr.result.lambda / 256.0 - id.lambda), bl);
        ASSERT_LE(std::abs(tr.result.lambda / 256.0 - id.lambda), bl) << g << " " << n;
        ++lambda_checked;
      }
      ++checked;
    }
  }
  for (const auto& [name, w] : worst) {
    std::printf("  %-7s largest error %.6g, largest error / bound %.3f\n", name.c_str(), w.err,
                w.ratio);
  }
  std::printf("  %d samples, %d with lambda checked\n", checked, lambda_checked);
  EXPECT_GT(checked, 100000);
}

// An affine map sampled into the grid: both interpolations reproduce it exactly at the
// truncated coordinate (the sums are exact; only the final rounding remains), and its Jacobian
// exactly: the spline's weights reproduce linear data whatever x2 and x3 are, and the
// extrapolated nodes continue it.
TEST(TauTest, AffineGridsExactInBothModes) {
  std::mt19937_64 rng(12);
  for (int g = 0; g < 200; ++g) {
    const Interp interp = g % 2 ? Interp::kSpline : Interp::kLinear;
    TauGrid grid;
    grid.config = {1 + static_cast<int>(rng() % 16), 1 + static_cast<int>(rng() % 16), interp};
    const int cs = grid.config.cells_s, ct = grid.config.cells_t;
    const int64_t u0 = static_cast<int64_t>(rng() % 20001) - 10000,
                  v0 = static_cast<int64_t>(rng() % 20001) - 10000;
    const int64_t a = static_cast<int64_t>(rng() % 40001) - 20000,
                  b = static_cast<int64_t>(rng() % 40001) - 20000;
    const int64_t c = static_cast<int64_t>(rng() % 40001) - 20000,
                  d = static_cast<int64_t>(rng() % 40001) - 20000;
    for (int j = 0; j <= ct; ++j) {
      for (int i = 0; i <= cs; ++i) {
        grid.u.push_back(static_cast<int32_t>(u0 + a * i + b * j));
        grid.v.push_back(static_cast<int32_t>(v0 + c * i + d * j));
      }
    }
    const tau::TauUnit unit = unit_of(grid);
    for (int n = 0; n < 300; ++n) {
      tau::Request r;
      r.s = static_cast<int32_t>(rng() % static_cast<uint64_t>((cs + 2) * 65536)) - 65536;
      r.t = static_cast<int32_t>(rng() % static_cast<uint64_t>((ct + 2) * 65536)) - 65536;
      const tau::Trace tr = unit.trace(r);
      // The truncated coordinate in units of 2^-12 cell.
      const int64_t sq = int64_t{tr.s.cell} * 4096 + tr.s.x,
                    tq = int64_t{tr.t.cell} * 4096 + tr.t.x;
      ASSERT_EQ(tr.sum_u, (u0 << 26) + ((a * sq + b * tq) << 14)) << g << " " << n;
      ASSERT_EQ(tr.sum_v, (v0 << 26) + ((c * sq + d * tq) << 14)) << g << " " << n;
      ASSERT_EQ(tr.jus, 4 * a);  // SQ18.10 texels per cell of a step in SQ16.8
      ASSERT_EQ(tr.jut, 4 * b);
      ASSERT_EQ(tr.jvs, 4 * c);
      ASSERT_EQ(tr.jvt, 4 * d);
    }
  }
}

// Linear mode on node lines: at a node the node itself; on the line s = i between two nodes
// the line's linear interpolation of them (x = 0 weights the next column zero).
TEST(TauTest, LinearOnNodeLines) {
  std::mt19937_64 rng(13);
  for (int g = 0; g < 50; ++g) {
    const TauGrid grid = draw_tau_grid(rng, TauGridKind::kRandom, 1 + static_cast<int>(rng() % 16),
                                       1 + static_cast<int>(rng() % 16), Interp::kLinear);
    const tau::TauUnit unit = unit_of(grid);
    const int cs = grid.config.cells_s, ct = grid.config.cells_t;
    for (int j = 0; j <= ct; ++j) {
      for (int i = 0; i <= cs; ++i) {
        const tau::Result r = unit.sample({i * 65536, j * 65536, 0, 0, 0, 0});
        const auto k = static_cast<size_t>(i + (cs + 1) * j);
        ASSERT_EQ(r.u, grid.u[k]);
        ASSERT_EQ(r.v, grid.v[k]);
      }
    }
    for (int n = 0; n < 200; ++n) {
      const int i = static_cast<int>(rng() % static_cast<uint64_t>(cs + 1));
      const int32_t t = static_cast<int32_t>(rng() % static_cast<uint64_t>(ct * 65536));
      const tau::Trace tr = unit.trace({i * 65536, t, 0, 0, 0, 0});
      const int j = tr.t.cell;
      const int64_t n0 = unit.node(i, j, false), n1 = unit.node(i, j + 1, false);
      const int64_t x = tr.t.x;
      // (n0 (4096 - x) + n1 x) / 4096, rounded half up.
      ASSERT_EQ(tr.result.u, (n0 * (4096 - x) + n1 * x + 2048) >> 12) << i << " " << t;
    }
  }
}

// lambda is the footprint setup's log2 |r_max| (footprint::plan with one probe and the sides
// rule), which is this formula on its log2_fixed: checked on the formula itself.
TEST(TauTest, LambdaIsTheFootprintSetupsLog2) {
  std::mt19937_64 rng(14);
  const TauGrid grid = draw_tau_grid(rng, TauGridKind::kSmooth, 4, 4, Interp::kSpline);
  const tau::TauUnit unit = unit_of(grid);
  for (int n = 0; n < 50000; ++n) {
    const auto d = [&rng] {
      const int shift = static_cast<int>(rng() % 23);
      return static_cast<int32_t>(rng() % (uint64_t{1} << shift)) * (rng() % 2 ? -1 : 1);
    };
    const tau::Result r =
        unit.sample({static_cast<int32_t>(rng() % (4 << 16)),
                     static_cast<int32_t>(rng() % (4 << 16)), d(), d(), d(), d()});
    const auto mag = [](int32_t c) { return static_cast<uint64_t>(c < 0 ? -int64_t{c} : c); };
    const uint64_t largest = std::max({mag(r.r1u), mag(r.r1v), mag(r.r2u), mag(r.r2v)});
    const int sh = std::max(0, static_cast<int>(std::bit_width(largest)) - 12);
    const auto sq = [sh, &mag](int32_t a, int32_t b) {
      return (mag(a) >> sh) * (mag(a) >> sh) + (mag(b) >> sh) * (mag(b) >> sh);
    };
    const uint64_t smax = std::max(sq(r.r1u, r.r1v), sq(r.r2u, r.r2v));
    const footprint::Log2 lg = footprint::log2_fixed(smax, footprint::Widths{12, 7, 8});
    const int64_t want = lg.zero ? -8192 : (lg.value + ((2 * sh - 16) << 8) + 1) >> 1;
    ASSERT_EQ(r.lambda, std::clamp<int64_t>(want, -8192, 8191));
  }
}

// Writes and samples take effect in the order presented: a node rewritten between two samples
// that read it changes the second only, on every engine, under stalls (golden = hls = rtl).
TEST(TauTest, WritesAndSamplesInOrder) {
  const TauBlock block;
  std::mt19937_64 rng(15);
  const TauGrid grid = draw_tau_grid(rng, TauGridKind::kSmooth, 2, 2, Interp::kSpline);
  std::vector<Txn> items = tau_load_items(grid);
  const tau::Request at = {70000, 80000, 1000, 0, 0, 1000};
  for (int k = 0; k < 20; ++k) {
    items.push_back(tau_sample_item(at));
    items.push_back(tau_node_item(1 + 17, (k + 1) * 2560, -k * 2560));  // node (1, 1)
  }
  items.push_back(tau_sample_item(at));
  RunOptions o;
  o.stalls = {7, 0.3, 0.5};
  const RunResult golden = block.engine("golden")->run(items, o);
  ASSERT_TRUE(golden.error.empty()) << golden.error;
  ASSERT_EQ(golden.outputs.size(), 21u);
  for (size_t k = 1; k < golden.outputs.size(); ++k) {
    EXPECT_NE(golden.outputs[k].f[desc::tau::out_u], golden.outputs[k - 1].f[desc::tau::out_u]);
  }
  for (const std::string level : {"hls", "rtl"}) {
    const RunResult r = block.engine(level)->run(items, o);
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs.size(), golden.outputs.size()) << level;
    for (size_t k = 0; k < r.outputs.size(); ++k) {
      EXPECT_EQ(r.outputs[k].f, golden.outputs[k].f) << level << ", output " << k;
    }
  }
}

// Cycles per sample, back to back without stalls: N + 7 (4 node reads linear, 16 spline), the
// accuracy a spline buys paid in time; the hls model spends the same cycles.
TEST(TauTest, CyclesPerSample) {
  const TauBlock block;
  std::mt19937_64 rng(16);
  for (const auto& [interp, cycles] :
       {std::pair{Interp::kLinear, 11u}, std::pair{Interp::kSpline, 23u}}) {
    const TauGrid grid = draw_tau_grid(rng, TauGridKind::kSmooth, 5, 5, interp);
    std::vector<Txn> items = tau_load_items(grid);
    for (int k = 0; k < 100; ++k) {
      items.push_back(tau_sample_item({k * 3000, k * 2000, 500, 0, 0, 500}));
    }
    for (const std::string level : {"rtl", "hls"}) {
      const RunResult r = block.engine(level)->run(items, RunOptions{});
      ASSERT_TRUE(r.error.empty()) << r.error;
      ASSERT_EQ(r.output_cycles.size(), 100u);
      for (size_t k = 1; k < r.output_cycles.size(); ++k) {
        EXPECT_EQ(r.output_cycles[k] - r.output_cycles[k - 1], cycles) << level << " " << k;
      }
    }
  }
}

}  // namespace
}  // namespace tmu::tb
