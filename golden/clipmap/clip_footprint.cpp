#include "clipmap/clip_footprint.hpp"

#include <array>
#include <span>

#include "formats/formats.hpp"

namespace tmu::clipmap {

uint32_t footprint_sample(const ClipMemory& memory, const Config& config, const Regions& regions,
                          const footprint::Config& setup, const footprint::Request& request,
                          std::vector<ClipPlan>* probe_plans) {
  const footprint::Plan p = footprint::plan(request, setup);
  std::array<uint32_t, 1 << formats::kMaxProbeLog2> colours{};
  const int n = 1 << p.log2_n;
  for (int i = 0; i < n; ++i) {
    ClipPlan plan;
    colours[static_cast<size_t>(i)] =
        sample(memory, config, regions, footprint::probe(request, p, i, config.sampler), &plan);
    if (probe_plans) probe_plans->push_back(plan);
  }
  return footprint::average(std::span(colours.data(), static_cast<size_t>(n)), p.log2_n);
}

}  // namespace tmu::clipmap
