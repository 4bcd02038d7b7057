// The footprint assembly unit's hls engine: the SystemC model (hls/footprint/footprint_sc.hpp)
// with its signals and the TEXRAM's eight banks (TexramMemory, the page model's timing, as the
// trilinear block's benches), driven by the harness's ScDriver in a forked child.
//
// Items and outputs as tb/blocks/footprint_env.hpp says. Counters: the memory's (accesses,
// bank_reads, page_faults, slow_accesses, address_hash) and probes (stat_probes_o at the end).
// The setup's and the trilinear unit's widths are env.config.widths and
// env.trilinear.config.widths.
#pragma once

#include <memory>

#include "blocks/footprint_env.hpp"
#include "harness/engine.hpp"

namespace tmu::tb {

std::unique_ptr<Engine> make_footprint_hls_engine(const FootprintEnv& env);

}  // namespace tmu::tb
