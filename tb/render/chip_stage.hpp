// The TEXRAM chips of a render (000 §14; docs/texram_chip.md "Rendering through the chip"): the
// scene compiled to DRF programs (render/drf_compile), each chip's memory filled with its maps,
// and each pass over a material's pixels one texram_chip unit: the pixels' parameter
// transactions in, their emitted samples and colours out. The chip replaces a chain's map units
// (trilinear per map, one per cube face) and its specular_combine; the units in front of it
// (normal encoder, deflection, coordinate generator, cube address, tau) stay and compute the
// parameters. `texsim render --chips N`.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "blocks/texram_chip/texram_chip_block.hpp"
#include "render/drf_compile.hpp"
#include "render/pipeline.hpp"

namespace tmu::render {

class ChipStage {
 public:
  // Compiles `scene` onto `chips` chips (InputError when a material does not fit). The chips'
  // memories are filled when a pass first needs one.
  ChipStage(const host::Scene& scene, const std::vector<MaterialTexture>& textures, int chips);

  // Whether the chips sample material m's maps; if not, why_not(m) says why (its maps then go
  // through the separate units as without chips).
  bool samples(size_t m) const { return why_not_[m].empty(); }
  const std::string& why_not(size_t m) const { return why_not_[m]; }
  const ScenePrograms& programs() const { return programs_; }

  // The mipmap generator (000 §12) has written material m's texture in its chip: every level
  // at the map's base, as `generated` holds them (Pipeline::generate_mipmaps, the mipgen units at
  // the render's level). Passes from now on read that pyramid; before, the map held the host's.
  void write_generated(size_t m, std::shared_ptr<const texram::TexramTexture> generated);

  // Pass `pass` of material m over the fragments `frags` (with a bump map pass 0 is the emit
  // DRF alone and pass 1 the rest; else only pass 0): params[k] the parameter transactions of
  // frags[k], the leading one first (its lead is set here). Runs one texram_chip unit at
  // `level`, kept in `units`, and returns each pixel's colour; `emitted` (when given) receives
  // each pixel's emitted sample (a pass that ends at an emit DRF).
  std::vector<uint32_t> run_pass(size_t m, size_t pass,
                                 std::vector<std::vector<texram::chip::PixelParameter>> params,
                                 const std::vector<size_t>& frags, Level level,
                                 std::vector<UnitRun>& units,
                                 std::vector<std::vector<size_t>>& outputs_of,
                                 std::vector<uint32_t>* emitted = nullptr);

 private:
  const host::Scene& scene_;
  ScenePrograms programs_;
  std::vector<std::string> why_not_;
  std::vector<std::shared_ptr<const tb::ChipScene>> memories_;  // per chip, when first used
  std::mutex memories_mutex_;  // materials shade on several threads (Pipeline::set_jobs)
};

// The parameter transaction of material `mat`'s texture DRF for the fragment whose texture
// coordinates are `at` (the raster's record, or the tau unit's in order pc): (u, v, lambda) and
// the shade I_d, and with footprint assembly its r1, r2 (the chip's marcher then finds lambda
// itself). One place for the plain pass and the effect chain's, so neither forgets r1, r2.
texram::chip::PixelParameter texture_parameter(const host::Material& mat,
                                               const host::FragmentRecord& at, uint32_t shade);

// For the report, per material of `scene`: "NAME: chip C, DRF 1 | 2 -> 3" (a pass ends at "|"),
// or "NAME: separate units: why".
std::vector<std::string> chip_lines(const host::Scene& scene, const ChipStage& chips);

}  // namespace tmu::render
