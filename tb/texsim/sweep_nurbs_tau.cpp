#include "texsim/sweep_nurbs_tau.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "blocks/tau/tau_block.hpp"
#include "nurbs/tau_map.hpp"
#include "render/tau_stage.hpp"
#include "render/unit_check.hpp"
#include "render/units.hpp"
#include "tau/tau_unit.hpp"

namespace tmu::texsim {
namespace {

using host::nurbs::TauMap;

constexpr glm::ivec2 kTextureSize{256, 256};
constexpr double kPcOne = 65536;  // PcCoord and PcDeriv: 16 fraction bits per cell

struct TauCase {
  std::string name;
  TauMap map;
  bool on_weight_grid = false;  // (s, t) where the unit's 12-bit weight fractions are exact
};

TauMap wave(int cells, tau::Interp interp) {
  TauMap m;
  m.kind = TauMap::Kind::kWave;
  m.amplitude = 0.05;
  m.frequency = 1.5;
  m.cells = {cells, cells};
  m.interp = interp;
  return m;
}

// At 8 cells its nodes are whole texels (u = 32 i + 16 j + 32, v = -16 i + 48 j + 16), so the
// grid holds the map exactly, and every slope is a multiple of 16 texels a cell, so that a
// weight fraction x / 2^12 moves (u, v) by whole 1/256 texels: nothing to round either.
TauMap affine(tau::Interp interp) {
  TauMap m;
  m.kind = TauMap::Kind::kAffine;
  m.matrix = glm::dmat2(1.0, -0.5, 0.5, 1.5);  // columns d(u, v)/ds, d(u, v)/dt
  m.offset = {0.125, 0.0625};
  m.cells = {8, 8};
  m.interp = interp;
  return m;
}

std::vector<TauCase> cases() {
  std::vector<TauCase> out;
  for (const tau::Interp interp : {tau::Interp::kLinear, tau::Interp::kSpline}) {
    const char* name = interp == tau::Interp::kLinear ? "linear" : "spline";
    for (const int cells : {1, 2, 4, 8, 16})
      out.push_back({fmt::format("wave {} {}", cells, name), wave(cells, interp)});
  }
  out.push_back({"affine 8 linear", affine(tau::Interp::kLinear), true});
  out.push_back({"affine 8 spline", affine(tau::Interp::kSpline), true});
  out.push_back({"affine 8 linear, any (s, t)", affine(tau::Interp::kLinear), false});
  return out;
}

// A screen derivative of (s, t) as the ports carry it: a random direction, a length of 2^-10
// .. 2^-2 of the map's range (a quarter texel to 64 texels a pixel on 256 texels), in cells.
std::pair<int32_t, int32_t> random_derivative(std::mt19937_64& rng, glm::ivec2 cells) {
  std::uniform_real_distribution<double> log_len(-10, -2), angle(0, 2 * std::numbers::pi);
  const double len = std::exp2(log_len(rng)), a = angle(rng);
  return {static_cast<int32_t>(std::lround(len * std::cos(a) * cells.x * kPcOne)),
          static_cast<int32_t>(std::lround(len * std::sin(a) * cells.y * kPcOne))};
}

tau::Request random_request(std::mt19937_64& rng, glm::ivec2 cells, bool on_weight_grid) {
  // The weight fraction is s's 12 bits below the cell (tau_unit.hpp, step 1): the low 4 of
  // PcCoord's 16 are truncated away.
  const auto coord = [&](int c) {
    if (on_weight_grid)
      return static_cast<int32_t>(std::uniform_int_distribution<int32_t>(0, c * 4096)(rng) * 16);
    return std::uniform_int_distribution<int32_t>(0, c * 65536)(rng);
  };
  tau::Request r;
  r.s = coord(cells.x);
  r.t = coord(cells.y);
  std::tie(r.ds_dx, r.dt_dx) = random_derivative(rng, cells);
  std::tie(r.ds_dy, r.dt_dy) = random_derivative(rng, cells);
  return r;
}

struct Exact {
  glm::dvec2 uv;  // texels
  double lambda;
};

// The functional map at the request's (s, t), its Jacobian applied to its derivatives.
Exact exact(const TauMap& map, const tau::Request& r) {
  const glm::dvec2 per_cell = 1.0 / (kPcOne * glm::dvec2(map.cells));  // raw -> normalised
  const host::nurbs::TauValue tv = host::nurbs::evaluate(map, r.s * per_cell.x, r.t * per_cell.y);
  const glm::dvec2 size(kTextureSize);
  const auto screen = [&](int32_t ds, int32_t dt) {
    return (tv.d_ds * (ds * per_cell.x) + tv.d_dt * (dt * per_cell.y)) * size;
  };
  const double longest =
      std::max(glm::length(screen(r.ds_dx, r.dt_dx)), glm::length(screen(r.ds_dy, r.dt_dy)));
  return {tv.uv * size, std::log2(longest)};
}

struct RtlFigures {
  bool match = false;
  double cycles_per_sample = 0;
};

// The tau block at rtl and golden over the grid's load and `requests`: outputs, counters.
// Cycles per sample from the first to the last output: the rate once the grid is loaded.
RtlFigures run_rtl(const tb::TauGrid& grid, const std::vector<tau::Request>& requests) {
  render::UnitRun rtl;
  rtl.kind = "tau";
  rtl.material = "sweep";
  render::attach(rtl, std::make_shared<tb::TauBlock>());
  rtl.items = tb::tau_load_items(grid);
  for (const tau::Request& r : requests) rtl.items.push_back(tb::tau_sample_item(r));
  render::UnitRun golden = rtl;
  render::run_unit(rtl, render::Level::kRtl, {});
  render::run_unit(golden, render::Level::kGolden, {});
  RtlFigures f;
  f.match = render::check_units({rtl}, {golden}).match();
  const std::vector<uint64_t>& at = rtl.result.output_cycles;
  if (at.size() > 1)
    f.cycles_per_sample = static_cast<double>(at.back() - at.front()) / double(at.size() - 1);
  return f;
}

}  // namespace

SweepTable tau_grid_table(size_t samples, size_t rtl_items) {
  SweepTable table({"map cells interp", Column("nodes", Mark::kFormula),
                    Column("uv max texels", Mark::kModel), Column("uv mean texels", Mark::kModel),
                    Column("lambda max", Mark::kModel), Column("lambda mean", Mark::kModel),
                    "rtl = golden", Column("cycles/sample", Mark::kSim)});
  for (const TauCase& c : cases()) {
    host::Material material;
    material.tau = c.map;
    const tb::TauGrid grid = render::tau_grid(material, kTextureSize);
    tau::TauUnit unit;
    unit.configure(grid.config);
    for (size_t i = 0; i < grid.u.size(); ++i) {
      const int cells_s = c.map.cells.x;
      const auto col = static_cast<uint32_t>(i % static_cast<size_t>(cells_s + 1));
      const auto row = static_cast<uint32_t>(i / static_cast<size_t>(cells_s + 1));
      unit.write(col + tau::kStride * row, grid.u[i], grid.v[i]);
    }
    std::mt19937_64 rng(2024);
    std::vector<tau::Request> requests;
    double uv_max = 0, uv_sum = 0, l_max = 0, l_sum = 0;
    for (size_t k = 0; k < samples; ++k) {
      const tau::Request r = random_request(rng, c.map.cells, c.on_weight_grid);
      if (requests.size() < rtl_items) requests.push_back(r);
      const tau::Result got = unit.sample(r);
      const Exact want = exact(c.map, r);
      const double uv = glm::length(glm::dvec2(got.u, got.v) / 256.0 - want.uv);
      const double l = std::abs(got.lambda / 256.0 - want.lambda);
      uv_max = std::max(uv_max, uv);
      uv_sum += uv;
      l_max = std::max(l_max, l);
      l_sum += l;
    }
    const RtlFigures rtl = run_rtl(grid, requests);
    const double n = static_cast<double>(std::max<size_t>(samples, 1));
    // An exact row says 0, not a rounded 0.0000.
    const auto texels = [](double x) {
      return x == 0 ? std::string("0") : fmt::format("{:.4f}", x);
    };
    table.add({c.name, fmt::format("{}", grid.u.size()), texels(uv_max), texels(uv_sum / n),
               fmt::format("{:.3f}", l_max), fmt::format("{:.4f}", l_sum / n),
               rtl.match ? "yes" : "NO", fmt::format("{:.2f}", rtl.cycles_per_sample)});
    fmt::print("  {}\n", table.last_row_text());
  }
  return table;
}

}  // namespace tmu::texsim
