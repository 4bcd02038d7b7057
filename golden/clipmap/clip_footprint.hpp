// Footprint assembly on a clip-map (000 §10 in front of 003): the footprint unit's setup and
// marcher (golden/footprint/footprint.hpp: plan, probe, average) with every probe a clip-map
// sample (clipmap.hpp) instead of a trilinear-unit sample, so that an anisotropic footprint over
// a texture far larger than texture memory reads the clip-map's tiles like every other sample.
// Each probe is substituted on its own (per sample or per tap, as the clip-map is configured):
// the probes of a long footprint that leave the finest tile come from a coarser one while the
// others stay fine. The marcher's coordinates are virtual (texels of the virtual level 0, up to
// 32k: TexCoord's range); a probe beyond the port wraps or saturates per the clip-map's border
// modes, as the footprint unit's does on its texture.
#pragma once

#include <cstdint>
#include <vector>

#include "clipmap/clipmap.hpp"
#include "footprint/footprint.hpp"

namespace tmu::clipmap {

// The fragment's colour, RGBA8888. `probe_plans` (optional) receives every probe's plan, in
// order (its memory accesses are read_accesses of each).
uint32_t footprint_sample(const ClipMemory& memory, const Config& config, const Regions& regions,
                          const footprint::Config& setup, const footprint::Request& request,
                          std::vector<ClipPlan>* probe_plans = nullptr);

}  // namespace tmu::clipmap
