// The host's side of the TEXRAM chip (000 §14, docs/texram_chip.md): every material whose maps
// the TEXRAM samples becomes a DRF program on a chip: its chain of DRFs (render/effect_chain's
// order), its maps placed in the chip's memory. Materials that need no TEXRAM map (procedural,
// the low-cost unit, clip-maps) get no program and are listed with the reason.
//
// Placement, in scene order, first fit over the chips given: a material's maps all on one chip
// (a pixel's chain runs on one chip), when the chip has DRFs left for its chain (a cube map
// needs DRF 7), cells left in its banks for every map (each map at a base aligned to a DRAM page,
// 512 cells, so no two maps share a page), and a CLUT it can share (index and CCC maps bring
// their palette; a chip has one). A material that fits no chip is a clear error (InputError:
// the scene file, `materials.NAME`, what it needs and what each chip has left).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/pipeline.hpp"
#include "scene/scene.hpp"
#include "texram/chip/drf.hpp"

namespace tmu::render {

// One map in a chip's memory.
struct ChipMap {
  std::string label;  // "floor", "shiny.environment+X"
  std::string role;   // the map's role in the material's chain ("" the texture, "bump", ...)
  int material = 0;
  int drf = 0;                                           // the DRF that reads it (1..7)
  int face = -1;                                         // a cube map's face 0..5
  uint32_t base = 0;                                     // its first cell in every bank
  uint32_t cells = 0;                                    // cells a bank (the fuller bank's)
  std::shared_ptr<const texram::TexramTexture> texture;  // what goes there
};

struct ChipProgram {
  texram::chip::DrfFile drfs{};
  std::vector<ChipMap> maps;
  uint32_t used_cells = 0;  // the next free cell (page aligned)
  int used_drfs = 0;        // DRFs 1..used_drfs are programmed (7 too with a cube)
  bool cube_used = false;
  std::optional<texram::Clut32> clut;  // the palette its index and CCC maps share
};

struct MaterialProgram {
  int material = 0;
  int chip = -1;          // -1: not on a chip (why)
  std::vector<int> drfs;  // the chain, leading DRF first
  // The leading DRF of each pass over the material's pixels: the chain, or with a bump map
  // the emit DRF alone and then the rest (its deflected coordinates come from outside).
  std::vector<int> passes;
  std::vector<std::string> parameters;  // what each parameter transaction of a pixel carries
  std::string why;                      // not on a chip: the reason
};

struct ScenePrograms {
  std::vector<ChipProgram> chips;
  std::vector<MaterialProgram> materials;  // one per scene material
};

// Compiles `scene` (its maps as `textures` holds them, from Pipeline) onto `chips` chips.
// Throws InputError when a material does not fit.
ScenePrograms compile_drfs(const host::Scene& scene, const std::vector<MaterialTexture>& textures,
                           int chips);

}  // namespace tmu::render
