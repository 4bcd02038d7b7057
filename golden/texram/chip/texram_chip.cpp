#include "texram/chip/texram_chip.hpp"

#include <algorithm>
#include <stdexcept>

#include "footprint/footprint.hpp"
#include "texram/specular_combine.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram::chip {

Geometry drf_geometry(const Drf& d) {
  const TexelKind k = d.sampler.kind;
  const bool four = k == TexelKind::kTrueColour || k == TexelKind::kCcc;
  return Geometry(d.log2_w, d.log2_h, four ? 4 : 1, k == TexelKind::kCcc);
}

uint32_t TexramChip::sample(int number, const Drf& d, const PixelParameter& p,
                            const Request& request) {
  const Geometry g = drf_geometry(d);
  const uint32_t base = d.cube ? d.face_base[static_cast<size_t>(p.face % kCubeFaces)] : d.base;
  const SamplePlan plan = plan_sample(g, d.sampler, request);  // addressing included
  AccessData data{};
  for (int plane = 0; plane < plan.planes; ++plane) {
    ChipAccess a;
    a.drf = number;
    bool any = false;
    for (unsigned b = 0; b < 8; ++b) {
      if (!plan.bank_address[b]) continue;
      const uint32_t cell = base + *plan.bank_address[b] + static_cast<uint32_t>(plane);
      a.address[b] = cell;
      data[b][static_cast<size_t>(plane)] = memory_.cell(static_cast<int>(b), cell);
      any = true;
    }
    if (!any) break;  // nothing to read (every tap outside): no access
    pages_.access(a.address);
    accesses_.push_back(a);
  }
  std::array<std::array<uint32_t, 4>, 2> colours{};
  for (int j = 0; j < plan.levels_read; ++j) {
    for (int k = 0; k < plan.taps_per_level; ++k) {
      colours[static_cast<size_t>(j)][static_cast<size_t>(k)] =
          tap_colour(plan.taps[static_cast<size_t>(j)][static_cast<size_t>(k)], data,
                     d.sampler.kind, d.sampler, clut_);
    }
  }
  return combine(blend_taps(plan, colours, d.sampler.widths), d.sampler, request.shade);
}

uint32_t TexramChip::assemble(int number, const Drf& d, const PixelParameter& p, uint32_t shade) {
  Request request = p.request;
  request.shade = shade;
  if (!d.footprint) return sample(number, d, p, request);
  const footprint::Request fr{request.u, request.v, p.r1u, p.r1v, p.r2u, p.r2v, shade};
  footprint::Config config;
  config.log2_max_probes = std::min(d.log2_max_probes, formats::kMaxProbeLog2);  // 5..7 act as 4
  config.q_rule = d.q_rule;
  const footprint::Plan plan = footprint::plan(fr, config);
  std::array<uint32_t, 1 << formats::kMaxProbeLog2> colours{};
  const int n = 1 << plan.log2_n;
  for (int i = 0; i < n; ++i) {
    colours[static_cast<size_t>(i)] =
        sample(number, d, p, footprint::probe(fr, plan, i, d.sampler));
  }
  return footprint::average(std::span(colours.data(), static_cast<size_t>(n)), plan.log2_n);
}

void TexramChip::pixel(const std::vector<PixelParameter>& params, size_t& next,
                       std::vector<ChipOutput>& out) {
  const auto take = [&]() -> const PixelParameter& {
    if (next >= params.size()) throw std::logic_error("TEXRAM chip: a pixel lacks a parameter");
    ++stats_.parameters;
    return params[next++];
  };
  ++stats_.pixels;
  const PixelParameter* p = &take();
  uint32_t shade = p->request.shade;
  uint32_t colour = 0, reflectance = 0, environment = 0;
  bool have_reflectance = false, have_environment = false, shaded_by_map = false;
  int number = p->lead & 7;
  for (int step = 0; number != 0; ++step) {
    if (step == kMaxSteps) {
      stats_.step_limit = true;
      break;
    }
    const Drf& d = drfs_[static_cast<size_t>(number - 1)];
    if (step > 0 && d.takes_coords) {
      p = &take();
      if (d.op == DrfOp::kTexture && !shaded_by_map) shade = p->request.shade;
    }
    ++stats_.steps;
    const uint32_t s = assemble(number, d, *p, shade);
    switch (d.op) {
      case DrfOp::kTexture:
        colour = s;
        break;
      case DrfOp::kShading:
        shade = s;
        shaded_by_map = true;
        break;
      case DrfOp::kReflectance:
        reflectance = s;
        have_reflectance = true;
        break;
      case DrfOp::kEnvironment:
        environment = s;
        if (!have_reflectance) reflectance = d.sampler.constant_rgba;
        have_environment = true;
        break;
      case DrfOp::kEmit:
        out.push_back({s, false});
        break;
      default:
        break;  // ops 5..7 do nothing
    }
    number = d.link;
  }
  out.push_back(
      {have_environment ? specular_combine(colour, environment, reflectance) : colour, true});
}

}  // namespace tmu::texram::chip
