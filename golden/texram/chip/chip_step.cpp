#include "texram/chip/chip_step.hpp"

#include <algorithm>
#include <array>
#include <span>

#include "footprint/footprint.hpp"
#include "texram/chip/texram_chip.hpp"
#include "texram/detail.hpp"

namespace tmu::texram::chip {
namespace {

const Drf& step_drf(const StepContext& c, int number) {
  return c.drfs[static_cast<size_t>(number - 1)];
}

// The map's own base, or the face's for DRF 7's cube map.
uint32_t face_or_base(const Drf& d, int face) {
  return d.cube ? d.face_base[static_cast<size_t>(face % kCubeFaces)] : d.base;
}

}  // namespace

uint32_t read_map(const StepContext& c, int number, const Drf& d, uint32_t base,
                  const Request& request, SamplePlan* plan_out) {
  const SamplePlan plan = plan_sample(drf_geometry(d), d.sampler, request);  // addressing too
  if (plan_out) *plan_out = plan;
  AccessData data{};
  if (std::any_of(plan.bank_address.begin(), plan.bank_address.end(),
                  [](const auto& a) { return a.has_value(); })) {
    c.reader.read(number, base, plan, data);  // nothing to read (every tap outside): no access
  }
  std::array<std::array<uint32_t, 4>, 2> colours{};
  for (int j = 0; j < plan.levels_read; ++j) {
    for (int k = 0; k < plan.taps_per_level; ++k) {
      colours[static_cast<size_t>(j)][static_cast<size_t>(k)] =
          tap_colour(plan.taps[static_cast<size_t>(j)][static_cast<size_t>(k)], data,
                     d.sampler.kind, d.sampler, c.clut);
    }
  }
  return combine(blend_taps(plan, colours, d.sampler.widths), d.sampler, request.shade);
}

uint32_t sample_with_detail(const StepContext& c, int number, int face, const Request& request) {
  const Drf& t = step_drf(c, number);
  const uint32_t t_base = face_or_base(t, face);
  const DetailLevels levels = detail_levels(t.sampler.widths, request.lambda);
  if (!t.detail || !levels.detail || t.link == 0) return read_map(c, number, t, t_base, request);
  const int o_number = t.link;
  const Drf& o = step_drf(c, o_number);
  if (o.link == 0) return read_map(c, number, t, t_base, request);
  const int d_number = o.link;
  const Drf& d = step_drf(c, d_number);
  // texram/detail.hpp's steps, each map read where its DRF says.
  const Request at_level0{request.u, request.v, 0, 0};
  SamplePlan plan_u;
  const uint32_t ou = channel(read_map(c, o_number, o, o.base, at_level0, &plan_u), 0);
  const uint32_t ov = channel(read_map(c, o_number, o, offsets_v_base(o), at_level0), 0);
  const DetailRegion region{plan_u.taps[0][0].outside, ou, ov};
  if (region.outside) {
    return read_map(c, number, t, t_base, {request.u, request.v, 0, request.shade});
  }
  const uint32_t colour =
      read_map(c, d_number, d, d.base, detail_request(region, request, levels.lambda_d));
  const bool modulate = t.detail_combine == DetailCombine::kModulate;
  uint32_t texel = 0;
  if (modulate || levels.wt != 0) {
    Drf one = t;
    one.sampler.combine = Combine::kOne;
    texel = read_map(c, number, one, t_base, at_level0);
  }
  const int w = t.sampler.widths.weight;
  const uint32_t mixed = modulate ? modulate_colour(colour, texel, levels.wt, w)
                                  : replace_colour(colour, texel, levels.wt, w);
  return combine(mixed, t.sampler, request.shade);
}

uint32_t sample_step(const StepContext& c, int number, const PixelParameter& p, uint32_t shade) {
  const Drf& t = step_drf(c, number);
  Request request = p.request;
  request.shade = shade;
  if (!t.footprint) return sample_with_detail(c, number, p.face, request);
  const footprint::Request fr{request.u, request.v, p.r1u, p.r1v, p.r2u, p.r2v, shade};
  footprint::Config config;
  config.log2_max_probes = std::min(t.log2_max_probes, formats::kMaxProbeLog2);  // 5..7 act as 4
  config.q_rule = t.q_rule;
  const footprint::Plan plan = footprint::plan(fr, config);
  std::array<uint32_t, 1 << formats::kMaxProbeLog2> colours{};
  const int n = 1 << plan.log2_n;
  for (int i = 0; i < n; ++i) {
    colours[static_cast<size_t>(i)] =
        sample_with_detail(c, number, p.face, footprint::probe(fr, plan, i, t.sampler));
  }
  return footprint::average(std::span(colours.data(), static_cast<size_t>(n)), plan.log2_n);
}

int next_drf(const DrfFile& file, const Drf& d, int* extra_steps) {
  if (extra_steps) *extra_steps = 0;
  const int number = d.link;
  if (!d.detail || number == 0) return number;
  const int detail_number = file[static_cast<size_t>(number - 1)].link;
  if (detail_number == 0) return number;
  if (extra_steps) *extra_steps = 2;
  return file[static_cast<size_t>(detail_number - 1)].link;
}

}  // namespace tmu::texram::chip
