#include "tau/tau_unit.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "footprint/footprint.hpp"
#include "formats/formats.hpp"

namespace tmu::tau {
namespace {

namespace fmts = tmu::formats;

constexpr int kCoordFrac = fmts::kPcCoord.frac_bits;  // 16
constexpr int kWeightFrac = 12;                       // x, x2, x3
constexpr int32_t kOne = int32_t{1} << 13;            // a weight of one
constexpr int kJacobianBits = 28;                     // SQ18.10

int64_t saturate(int64_t value, int bits, bool& saturated) {
  const int64_t hi = (int64_t{1} << (bits - 1)) - 1, lo = -(int64_t{1} << (bits - 1));
  if (value > hi || value < lo) saturated = true;
  return std::clamp(value, lo, hi);
}

// Round half up of value / 2^shift (arithmetic: floor of value / 2^shift + 1/2).
int64_t round_shift(int64_t value, int shift) {
  return (value + (int64_t{1} << (shift - 1))) >> shift;
}

// The port's 24 bits of a node value, sign-extended.
int32_t wrap24(int32_t value) {
  constexpr int kW = fmts::kTexCoord.width();
  return static_cast<int32_t>(static_cast<uint32_t>(value) << (32 - kW)) >> (32 - kW);
}

}  // namespace

int effective_cells(int cells) { return std::clamp(cells, 1, kMaxCells); }

AxisWeights axis_weights(int32_t coord, int cells, Interp interp) {
  AxisWeights a;
  const int64_t s = std::clamp<int64_t>(coord, 0, int64_t{cells} << kCoordFrac);
  a.cell = std::min(static_cast<int>(s >> kCoordFrac), cells - 1);
  a.x = static_cast<int32_t>((s - (int64_t{a.cell} << kCoordFrac)) >> (kCoordFrac - kWeightFrac));
  const int32_t half = int32_t{1} << (kWeightFrac - 1);
  a.x2 = (a.x * a.x + half) >> kWeightFrac;
  a.x3 = (a.x2 * a.x + half) >> kWeightFrac;
  const int32_t x = a.x, x2 = a.x2, x3 = a.x3;
  if (interp == Interp::kSpline) {
    a.first = a.cell - 1;
    a.count = 4;
    a.c = {-x3 + 2 * x2 - x, 3 * x3 - 5 * x2 + kOne, -3 * x3 + 4 * x2 + x, x3 - x2};
    a.d = {-3 * x2 + 4 * x - kOne / 2, 9 * x2 - 10 * x, -9 * x2 + 8 * x + kOne / 2, 3 * x2 - 2 * x};
  } else {
    a.first = a.cell;
    a.count = 2;
    a.c = {2 * ((int32_t{1} << kWeightFrac) - x), 2 * x, 0, 0};
    a.d = {-kOne, kOne, 0, 0};
  }
  return a;
}

void TauUnit::configure(const Config& config) {
  config_ = config;
  config_.cells_s = effective_cells(config.cells_s);
  config_.cells_t = effective_cells(config.cells_t);
}

void TauUnit::write(uint32_t addr, int32_t u, int32_t v) {
  if (addr >= static_cast<uint32_t>(kNodes)) return;  // no such word: ignored
  u_[addr] = wrap24(u);
  v_[addr] = wrap24(v);
  written_.set(addr);
}

int64_t TauUnit::node(int i, int j, bool v) const {
  const int cs = config_.cells_s, ct = config_.cells_t;
  if (i < 0) return 2 * node(0, j, v) - node(1, j, v);
  if (i > cs) return 2 * node(cs, j, v) - node(cs - 1, j, v);
  if (j < 0) return 2 * node(i, 0, v) - node(i, 1, v);
  if (j > ct) return 2 * node(i, ct, v) - node(i, ct - 1, v);
  const auto addr = static_cast<size_t>(i + kStride * j);
  if (!written_.test(addr)) {
    throw std::runtime_error("tau: a sample reads node (" + std::to_string(i) + ", " +
                             std::to_string(j) +
                             "), which no write has set (the node memory is a RAM without "
                             "reset: write every node of the grid first)");
  }
  return v ? v_[addr] : u_[addr];
}

Trace TauUnit::trace(const Request& r) const {
  Trace tr;
  tr.s = axis_weights(r.s, config_.cells_s, config_.interp);
  tr.t = axis_weights(r.t, config_.cells_t, config_.interp);
  for (int b = 0; b < tr.t.count; ++b) {
    const int j = tr.t.first + b;
    for (int a = 0; a < tr.s.count; ++a) {
      const int i = tr.s.first + a;
      if (i < 0 || i > config_.cells_s || j < 0 || j > config_.cells_t) tr.extrapolated = true;
      const int64_t nu = node(i, j, false), nv = node(i, j, true);
      const int64_t w = int64_t{tr.s.c[a]} * tr.t.c[b];   // Cs Ct
      const int64_t ws = int64_t{tr.s.d[a]} * tr.t.c[b];  // Ds Ct
      const int64_t wt = int64_t{tr.s.c[a]} * tr.t.d[b];  // Cs Dt
      tr.sum_u += w * nu;
      tr.sum_v += w * nv;
      tr.sum_us += ws * nu;
      tr.sum_vs += ws * nv;
      tr.sum_ut += wt * nu;
      tr.sum_vt += wt * nv;
    }
  }
  constexpr int kCoordW = fmts::kTexCoord.width();
  constexpr int kDerivW = fmts::kTexDeriv.width();
  Result& out = tr.result;
  out.u = static_cast<int32_t>(saturate(round_shift(tr.sum_u, 26), kCoordW, tr.uv_saturated));
  out.v = static_cast<int32_t>(saturate(round_shift(tr.sum_v, 26), kCoordW, tr.uv_saturated));
  const auto jacobian = [&tr](int64_t sum) {
    return static_cast<int32_t>(saturate(round_shift(sum, 24), kJacobianBits, tr.j_saturated));
  };
  tr.jus = jacobian(tr.sum_us);
  tr.jut = jacobian(tr.sum_ut);
  tr.jvs = jacobian(tr.sum_vs);
  tr.jvt = jacobian(tr.sum_vt);
  const auto r_of = [&tr](int32_t js, int32_t jt, int32_t ds, int32_t dt) {
    const int64_t sum = int64_t{js} * ds + int64_t{jt} * dt;
    return static_cast<int32_t>(saturate(round_shift(sum, 18), kDerivW, tr.r_saturated));
  };
  out.r1u = r_of(tr.jus, tr.jut, r.ds_dx, r.dt_dx);
  out.r1v = r_of(tr.jvs, tr.jvt, r.ds_dx, r.dt_dx);
  out.r2u = r_of(tr.jus, tr.jut, r.ds_dy, r.dt_dy);
  out.r2v = r_of(tr.jvs, tr.jvt, r.ds_dy, r.dt_dy);

  // lambda: the footprint setup's log2 |r_max| (with one probe at most and the sides rule its
  // lambda is exactly that, rounded to SQ6.8 and saturated; both vectors zero: the smallest).
  footprint::Request fr;
  fr.r1u = out.r1u;
  fr.r1v = out.r1v;
  fr.r2u = out.r2u;
  fr.r2v = out.r2v;
  footprint::Config fc;
  fc.log2_max_probes = 0;
  fc.q_rule = footprint::QRule::kSides;
  fc.widths = footprint::Widths{12, 7, 8};
  out.lambda = footprint::plan(fr, fc).lambda;
  return tr;
}

}  // namespace tmu::tau
