#include "texram/chip/texram_chip.hpp"

#include <algorithm>
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
    int extra = 0;
    number = next_drf(file, d, &extra);
    step += extra;
  }
  return params;
}

void TexramChip::read(int drf, uint32_t base, const SamplePlan& plan, AccessData& data) {
  for (int plane = 0; plane < plan.planes; ++plane) {
    ChipAccess a;
    a.drf = drf;
    for (unsigned b = 0; b < 8; ++b) {
      if (!plan.bank_address[b]) continue;
      const uint32_t cell = base + *plan.bank_address[b] + static_cast<uint32_t>(plane);
      a.address[b] = cell;
      data[b][static_cast<size_t>(plane)] = memory_.cell(static_cast<int>(b), cell);
    }
    pages_.access(a.address);
    accesses_.push_back(a);
  }
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
  const StepContext context{drfs_, clut_, *this};
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
    const uint32_t s = sample_step(context, number, *p, regs.shade);
    if (regs.apply(d, s)) out.push_back({s, false});
    // A detail map's offsets and detail DRFs were visited within this DRF's sample: the chain
    // goes on after them (they count as steps).
    int extra = 0;
    number = next_drf(drfs_, d, &extra);
    step += extra;
    stats_.steps += static_cast<uint64_t>(extra);
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
