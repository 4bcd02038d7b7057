// One step of the TEXRAM chip's sequencer (docs/texram_chip.md): what a DRF's sample is, with
// footprint assembly (000 §10) and a detail map (000 §9), written once over any memory. The
// golden chip (texram_chip.hpp) reads its memory through the page model; the hls model
// (hls/texram/texram_chip_sc.hpp) clocks the same accesses out of its ports. Both call these
// functions, so the arithmetic and the order of the accesses are the same code.
//
// A step on DRF t at parameter p, shade I_d (sample_step):
// - footprint off: one sample (below) at p's (u, v, lambda) with I_d;
// - footprint on: footprint::plan from p's (u, v, r1, r2) with t's log2_max_probes (5..7 act
//   as 4) and q_rule at the default widths, then N = 2^k samples at footprint::probe's
//   positions (wrapped or saturated by t's border modes) and the plan's lambda, averaged per
//   channel (footprint::average).
// One sample (sample_with_detail): t's map read as the trilinear unit reads it (its base, or
// the cube face's for DRF 7's cube map), or, when t.detail, lambda < 0 (texram::detail_levels)
// and t links to an offsets DRF o that links to a detail DRF d (links only, ops not checked),
// texram::sample_detail's steps: o's map at (u, v, 0, shade 0) at o.base and at
// offsets_v_base(o) (the offsets: the colours' red channel; no region when the u read's first
// tap of level 0 is outside o's map), d's map at detail_request (d.base), t's map at level 0
// with combine "one" when needed, the combine rule, then t's eq. 5 with the shade. Without a
// region: t's map at (u, v, 0, shade).
#pragma once

#include <cstdint>

#include "texram/chip/drf.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram::chip {

struct PixelParameter;

// Where a map is read: the bytes of `plan`'s cells at `base` (bank b's cell + plane p, for the
// plan's planes), on behalf of DRF `drf`. Called only for plans that read a bank.
class ChipReader {
 public:
  virtual ~ChipReader() = default;
  virtual void read(int drf, uint32_t base, const SamplePlan& plan, AccessData& data) = 0;
};

// What a step needs besides its DRF: the program, the chip's CLUT and the memory.
struct StepContext {
  const DrfFile& drfs;
  const Clut32& clut;
  ChipReader& reader;
};

// The trilinear datapath on DRF `number` (`d`) at `base`: its colour with d's eq. 5 and the
// request's shade; the plan through plan_out.
uint32_t read_map(const StepContext& c, int number, const Drf& d, uint32_t base,
                  const Request& request, SamplePlan* plan_out = nullptr);

// One sample of DRF `number` (t) at `request` (the rules above); `face` picks a cube map's face.
uint32_t sample_with_detail(const StepContext& c, int number, int face, const Request& request);

// The step: DRF `number`'s sample for parameter p with the pixel's shade.
uint32_t sample_step(const StepContext& c, int number, const PixelParameter& p, uint32_t shade);

// The DRF after `d` in a chain: its link, or past its offsets and detail DRFs when d has a
// detail map and both exist (they are visited within d's step); `extra_steps` (optional)
// receives the steps they count for (0 or 2).
int next_drf(const DrfFile& file, const Drf& d, int* extra_steps = nullptr);

}  // namespace tmu::texram::chip
