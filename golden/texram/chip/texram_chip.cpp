#include "texram/chip/texram_chip.hpp"

#include <algorithm>
#include <stdexcept>

#include "footprint/footprint.hpp"
#include "texram/detail.hpp"
#include "texram/specular_combine.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram::chip {

Geometry drf_geometry(const Drf& d) {
  const TexelKind k = d.sampler.kind;
  const bool four = k == TexelKind::kTrueColour || k == TexelKind::kCcc;
  return Geometry(d.log2_w, d.log2_h, four ? 4 : 1, k == TexelKind::kCcc);
}

int pixel_parameters(const DrfFile& file, int lead) {
  int params = 1;
  int number = lead & 7;
  for (int step = 0; number != 0 && step < kMaxSteps; ++step) {  // pixel()'s walk
    const Drf& d = file[static_cast<size_t>(number - 1)];
    if (step > 0 && d.takes_coords) ++params;
    number = d.link;
    if (d.detail && number != 0) {  // its offsets and detail DRFs
      const int detail_number = file[static_cast<size_t>(number - 1)].link;
      if (detail_number != 0) {
        number = file[static_cast<size_t>(detail_number - 1)].link;
        step += 2;
      }
    }
  }
  return params;
}

uint32_t TexramChip::sample(int number, const Drf& d, const PixelParameter& p,
                            const Request& request) {
  return read(number, d, d.cube ? d.face_base[static_cast<size_t>(p.face % kCubeFaces)] : d.base,
              request, nullptr);
}

uint32_t TexramChip::read(int number, const Drf& d, uint32_t base, const Request& request,
                          SamplePlan* plan_out) {
  const Geometry g = drf_geometry(d);
  const SamplePlan plan = plan_sample(g, d.sampler, request);  // addressing included
  if (plan_out) *plan_out = plan;
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

uint32_t TexramChip::with_detail(int number, const Drf& t, const PixelParameter& p,
                                 const Request& request) {
  const DetailLevels levels = detail_levels(t.sampler.widths, request.lambda);
  if (!t.detail || !levels.detail || t.link == 0) return sample(number, t, p, request);
  const int o_number = t.link;
  const Drf& o = drfs_[static_cast<size_t>(o_number - 1)];
  if (o.link == 0) return sample(number, t, p, request);
  const int d_number = o.link;
  const Drf& d = drfs_[static_cast<size_t>(d_number - 1)];
  // texram/detail.hpp's steps, each map read where its DRF says.
  const Request at_level0{request.u, request.v, 0, 0};
  SamplePlan plan_u;
  const uint32_t ou = channel(read(o_number, o, o.base, at_level0, &plan_u), 0);
  const uint32_t ov = channel(read(o_number, o, offsets_v_base(o), at_level0, nullptr), 0);
  const DetailRegion region{plan_u.taps[0][0].outside, ou, ov};
  if (region.outside) return sample(number, t, p, {request.u, request.v, 0, request.shade});
  const uint32_t colour =
      read(d_number, d, d.base, detail_request(region, request, levels.lambda_d), nullptr);
  const bool modulate = t.detail_combine == DetailCombine::kModulate;
  uint32_t texel = 0;
  if (modulate || levels.wt != 0) {
    Drf one = t;
    one.sampler.combine = Combine::kOne;
    texel = sample(number, one, p, at_level0);
  }
  const int w = t.sampler.widths.weight;
  const uint32_t c = modulate ? modulate_colour(colour, texel, levels.wt, w)
                              : replace_colour(colour, texel, levels.wt, w);
  return combine(c, t.sampler, request.shade);
}

uint32_t TexramChip::assemble(int number, const Drf& d, const PixelParameter& p, uint32_t shade) {
  Request request = p.request;
  request.shade = shade;
  if (!d.footprint) return with_detail(number, d, p, request);
  const footprint::Request fr{request.u, request.v, p.r1u, p.r1v, p.r2u, p.r2v, shade};
  footprint::Config config;
  config.log2_max_probes = std::min(d.log2_max_probes, formats::kMaxProbeLog2);  // 5..7 act as 4
  config.q_rule = d.q_rule;
  const footprint::Plan plan = footprint::plan(fr, config);
  std::array<uint32_t, 1 << formats::kMaxProbeLog2> colours{};
  const int n = 1 << plan.log2_n;
  for (int i = 0; i < n; ++i) {
    colours[static_cast<size_t>(i)] =
        with_detail(number, d, p, footprint::probe(fr, plan, i, d.sampler));
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
  PixelRegisters regs;
  regs.shade = p->request.shade;
  int number = p->lead & 7;
  for (int step = 0; number != 0; ++step) {
    if (step >= kMaxSteps) {
      stats_.step_limit = true;
      break;
    }
    const Drf& d = drfs_[static_cast<size_t>(number - 1)];
    if (step > 0 && d.takes_coords) {
      p = &take();
      regs.take_parameter(d, p->request.shade);
    }
    ++stats_.steps;
    const uint32_t s = assemble(number, d, *p, regs.shade);
    if (regs.apply(d, s)) out.push_back({s, false});
    number = d.link;
    // A detail map's offsets and detail DRFs were visited within this DRF's sample: the chain
    // goes on after them (they count as steps).
    if (d.detail && number != 0) {
      const int detail_number = drfs_[static_cast<size_t>(number - 1)].link;
      if (detail_number != 0) {
        number = drfs_[static_cast<size_t>(detail_number - 1)].link;
        step += 2;
        stats_.steps += 2;
      }
    }
  }
  out.push_back({regs.result(), true});
}

bool PixelRegisters::apply(const Drf& d, uint32_t sample) {
  switch (d.op) {
    case DrfOp::kTexture:
      colour = sample;
      return false;
    case DrfOp::kShading:
      shade = sample;
      shaded_by_map = true;
      return false;
    case DrfOp::kReflectance:
      reflectance = sample;
      have_reflectance = true;
      return false;
    case DrfOp::kEnvironment:
      environment = sample;
      if (!have_reflectance) reflectance = d.sampler.constant_rgba;
      have_environment = true;
      return false;
    case DrfOp::kEmit:
      return true;
    default:
      return false;  // an offsets or detail DRF reached on its own, op 7: read, nothing more
  }
}

uint32_t PixelRegisters::result() const {
  return have_environment ? specular_combine(colour, environment, reflectance) : colour;
}

}  // namespace tmu::texram::chip
