#include "texram/chip/texram_chip.hpp"

#include <stdexcept>

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
  }
  return params;
}

uint32_t TexramChip::sample(int number, const Drf& d, const PixelParameter& p, uint32_t shade) {
  const Geometry g = drf_geometry(d);
  const uint32_t base = d.cube ? d.face_base[static_cast<size_t>(p.face % kCubeFaces)] : d.base;
  const SamplePlan plan = plan_sample(g, d.sampler, p.request);  // addressing included
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
  stats_.pages = pages_.stats();  // stats() reports the page model's counts
  std::array<std::array<uint32_t, 4>, 2> colours{};
  for (int j = 0; j < plan.levels_read; ++j) {
    for (int k = 0; k < plan.taps_per_level; ++k) {
      colours[static_cast<size_t>(j)][static_cast<size_t>(k)] =
          tap_colour(plan.taps[static_cast<size_t>(j)][static_cast<size_t>(k)], data,
                     d.sampler.kind, d.sampler, clut_);
    }
  }
  return combine(blend_taps(plan, colours, d.sampler.widths), d.sampler, shade);
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
    const uint32_t s = sample(number, d, *p, shade);
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
