#include "render/tau_stage.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "formats/formats.hpp"
#include "nurbs/tau_map.hpp"
#include "raster/rasterizer.hpp"

namespace tmu::render {
namespace {

// PcCoord and PcDeriv: the fragment's TexCoord and TexDeriv raw values read with 16 fraction
// bits (the rasterizer's uv scale is 256 per cell).
constexpr double kPcPerTexCoordUnit = 1.0 / 256;

int32_t tex_coord(double texels) {
  return static_cast<int32_t>(formats::TexCoord::from_double(texels, fx::Round::kHalfEven).raw());
}

}  // namespace

glm::ivec2 pc_uv_scale(const host::Material& material) { return 256 * material.tau->cells; }

tb::TauGrid tau_grid(const host::Material& material, glm::ivec2 texture_size) {
  const tau::GridD g = host::nurbs::hardware_grid(*material.tau, texture_size);
  tb::TauGrid grid;
  grid.config = {g.cells_s, g.cells_t, material.tau->interp};
  for (size_t i = 0; i < g.u.size(); ++i) {
    grid.u.push_back(tex_coord(g.u[i]));
    grid.v.push_back(tex_coord(g.v[i]));
  }
  return grid;
}

std::vector<host::FragmentRecord> run_tau(const host::Material& material, glm::ivec2 texture_size,
                                          const std::vector<host::FragmentRecord>& records,
                                          const std::vector<size_t>& frags, Level level,
                                          std::vector<UnitRun>& units,
                                          std::vector<std::vector<size_t>>& outputs_of) {
  UnitRun run;
  run.kind = "tau";
  run.material = material.name;
  attach(run, std::make_shared<tb::TauBlock>());
  run.items = tb::tau_load_items(tau_grid(material, texture_size));
  for (size_t i : frags) {
    const host::FragmentRecord& r = records[i];
    run.items.push_back(tb::tau_sample_item({r.u, r.v, r.r1[0], r.r1[1], r.r2[0], r.r2[1]}));
  }
  const std::vector<tb::Txn> out = run_and_keep(std::move(run), level, frags, units, outputs_of);
  std::vector<host::FragmentRecord> mapped = records;
  for (size_t k = 0; k < frags.size(); ++k) {
    const tau::Result t = tb::tau_result_of(out[k]);
    host::FragmentRecord& r = mapped[frags[k]];
    r.u = t.u;
    r.v = t.v;
    r.r1[0] = t.r1u;
    r.r1[1] = t.r1v;
    r.r2[0] = t.r2u;
    r.r2[1] = t.r2v;
    r.lambda = t.lambda;
  }
  return mapped;
}

host::Fragment ideal_tau(const host::Material& material, glm::ivec2 texture_size,
                         const host::Fragment& f) {
  const glm::dvec2 cells(material.tau->cells);
  // The fragment's uv is (s, t) times 256 cells: back to normalised (s, t).
  const glm::dvec2 to_pc = kPcPerTexCoordUnit / cells;
  const host::nurbs::TauValue tv =
      host::nurbs::evaluate(*material.tau, f.uv.x * to_pc.x, f.uv.y * to_pc.y);
  const glm::dvec2 size(texture_size);
  host::Fragment g = f;
  g.uv = tv.uv * size;
  const auto map = [&](const glm::dvec2& d) {
    return (tv.d_ds * (d.x * to_pc.x) + tv.d_dt * (d.y * to_pc.y)) * size;
  };
  g.r1 = map(f.r1);
  g.r2 = map(f.r2);
  g.lambda = std::log2(std::max({glm::length(g.r1), glm::length(g.r2), host::kMinFootprint}));
  return g;
}

}  // namespace tmu::render
