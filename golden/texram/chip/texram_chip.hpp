// Golden model of the TEXRAM chip's sequencer (000 §14; docs/texram_chip.md): a pixel enters
// with the number of its leading DRF and its first parameter; the chip samples the DRF's map in
// the shared memory with the trilinear datapath (texram/trilinear.hpp: the same plan, taps,
// blend and eq. 5, the map's cells at base + its layout's address), does what the DRF's op says
// with the sample, and follows the link, taking the pixel's next parameter first where the DRF
// asks for new coordinates, until a link is 0. Every access goes through one page model.
//
// Per pixel, registers: I_d (the parameter's shade, or a shading map's sample), C_d (the
// texture's eq. 5), R (a reflectance map's sample; else the environment DRF's constant k_s),
// E (the environment's sample). The pixel's colour is C_d, or min(255, C_d + R E / 255) per
// channel (eq. 6-7, texram/specular_combine.hpp) once an environment was sampled. An emit DRF's
// sample leaves the chip at once (not last); the colour leaves last. After kMaxSteps accesses
// the pixel ends where it is and the sticky step_limit flag is set (the host never programs
// such a chain; check_program refuses it).
#pragma once

#include <cstdint>
#include <vector>

#include "texram/chip/chip_memory.hpp"
#include "texram/chip/chip_step.hpp"
#include "texram/chip/drf.hpp"
#include "texram/page_model.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::texram::chip {

// One parameter transaction of a pixel: the first names the leading DRF.
struct PixelParameter {
  int lead = 1;              // DrfIndex, read from a pixel's first parameter only
  Request request;           // u, v (or uN, vN), lambda, shade I_d
  int32_t r1u = 0, r1v = 0;  // TexDeriv: d(u, v)/dx, for a DRF with footprint assembly
  int32_t r2u = 0, r2v = 0;  // TexDeriv: d(u, v)/dy
  int face = 0;              // CubeFace, for DRF 7's cube map
};

struct ChipOutput {
  uint32_t rgba = 0;  // Rgba8888
  bool last = false;  // the pixel's colour; false: an emit DRF's sample
  friend bool operator==(const ChipOutput&, const ChipOutput&) = default;
};

// One access of the shared memory: the cell read in each bank (nothing where empty).
struct ChipAccess {
  std::array<std::optional<uint32_t>, 8> address{};
  int drf = 0;
  friend bool operator==(const ChipAccess&, const ChipAccess&) = default;
};

// A pixel's registers and what a DRF's op does with its sample: the sequencer's combine, one
// piece for the golden model and the hls model.
struct PixelRegisters {
  uint32_t shade = 0, colour = 0, reflectance = 0, environment = 0;
  bool have_reflectance = false, have_environment = false, shaded_by_map = false;
  // A texture DRF's new parameter brings I_d, unless a shading map has set it.
  void take_parameter(const Drf& d, uint32_t parameter_shade) {
    if (d.op == DrfOp::kTexture && !shaded_by_map) shade = parameter_shade;
  }
  // Keeps `sample` as d's op says; true when it leaves the chip at once (emit).
  bool apply(const Drf& d, uint32_t sample);
  // The pixel's colour: C_d, or eq. 6-7 once an environment was sampled.
  uint32_t result() const;
};

struct ChipStats {
  uint64_t pixels = 0, parameters = 0, steps = 0;  // steps: DRF visits (a detail map's: 3)
  PageStats pages;                                 // the shared memory's page model
  bool step_limit = false;                         // sticky: a pixel ran into kMaxSteps
};

class TexramChip : private ChipReader {
 public:
  // `memory` holds the maps (place() them first), `clut` the chip's palette.
  TexramChip(const ChipMemory& memory, const Clut32& clut) : memory_(memory), clut_(clut) {}

  void write(const DrfWrite& w) { apply(drfs_, w); }
  const DrfFile& drfs() const { return drfs_; }

  // Runs one pixel: takes its parameters from `params` starting at `next` (advanced past the
  // ones it takes) and appends its outputs. Throws std::logic_error when the chain needs a
  // parameter the list does not have.
  void pixel(const std::vector<PixelParameter>& params, size_t& next, std::vector<ChipOutput>& out);

  ChipStats stats() const {
    ChipStats s = stats_;
    s.pages = pages_.stats();
    return s;
  }
  const std::vector<ChipAccess>& accesses() const { return accesses_; }

 private:
  // ChipReader: the cells from the memory, each plane one access through the page model.
  void read(int drf, uint32_t base, const SamplePlan& plan, AccessData& data) override;

  const ChipMemory& memory_;
  const Clut32& clut_;
  DrfFile drfs_{};
  PageModel pages_;
  ChipStats stats_;
  std::vector<ChipAccess> accesses_;
};

// The parameter transactions a pixel led by `lead` takes under `file`: its first, and one per
// takes_coords DRF that pixel() reaches after it (step limit included). What a driver (and the
// co-simulation block) sends for one pixel.
int pixel_parameters(const DrfFile& file, int lead);

// The planes (accesses per sample) and the block grid a DRF's kind implies.
Geometry drf_geometry(const Drf& d);

}  // namespace tmu::texram::chip
