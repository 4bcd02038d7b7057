// A material's deflection chain (001 §6, 000 §7-8), unit by unit, each unit the
// co-simulation block at the pipeline's level, fed with the previous units' outputs:
//   normal_encoder          N (world space, SQ2.14)      -> (phi_N, theta_N)
//   trilinear[.bump]        bump map at (u, v), nearest  -> D = (phi_D, theta_D)   with bump
//   deflect                 (phi_N, theta_N), D          -> deflected (phi, theta) with bump
//   coord_gen               (phi, theta)                 -> (uN, vN), R = (uR, vR, wR)
//   trilinear[.diffuse]     diffuse map at (uN, vN)      -> I_d                    shading maps
//   trilinear / footprint   the texture, eq. 5 with I_d  -> C_d
//   trilinear[.specular] or [.environment] at (uN, vN), or
//   cube_address + trilinear[.environment+X] at R            -> I_s or E
//   trilinear[.reflectance] at (u, v, lambda)            -> R                      with a map
//   specular_combine        C = C_d + R . (E | I_s)      (000 eq. 6-7)
// Only the units the material names are built. The coordinate tables are loaded through the
// coordinate generator's write port from the camera's view frame (render/effect_maps.hpp).
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "raster/fragment.hpp"
#include "render/pipeline.hpp"
#include "scene/scene.hpp"

namespace tmu::render {

class ChipStage;

struct ChainInput {
  const host::Scene& scene;
  const host::Material& material;
  const MaterialTexture& texture;
  Level level;
  const std::vector<host::FragmentRecord>& records;
  const std::vector<size_t>& frags;  // the material's fragments, indices into records
  // The chips, when they sample this material's maps (ChipStage::samples): the chain's map
  // units and its specular_combine become passes of the chip (render/chip_stage.hpp).
  ChipStage* chip = nullptr;
  size_t material_index = 0;  // in the scene (for the chip)
};

// Runs the chain at in.level (not ideal); appends every unit it ran to `units` and the
// fragment index of each of its outputs to `outputs_of`. Returns RGBA8888 per frags entry.
std::vector<uint32_t> run_effect_chain(const ChainInput& in, std::vector<UnitRun>& units,
                                       std::vector<std::vector<size_t>>& outputs_of);

// What run_effect_chain computes on the host for `material` (its stages that are not yet a
// unit's), with the reason.
std::vector<HostWork> effect_chain_host_work(const host::Material& material, const EffectMaps& maps,
                                             bool on_chip);

// The ideal: the exact normal rotated by the bump texel's exact angles, exact map coordinates
// and reflection vector, the maps sampled there by the ideal trilinear unit, eq. 5-7 in
// double precision (clamped at 255, as the hardware saturates). `fragments` as records.
std::vector<glm::dvec4> ideal_effect_chain(const ChainInput& in,
                                           const std::vector<host::Fragment>& fragments);

}  // namespace tmu::render
