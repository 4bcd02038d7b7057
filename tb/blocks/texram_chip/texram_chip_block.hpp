// The TEXRAM chip as a co-simulation block, `texsim cosim texram_chip` (000 §14;
// docs/texram_chip.md "The chip block"; golden/texram/chip/texram_chip.hpp,
// rtl/texram/tmu_texram_chip.sv, hls/texram/texram_chip_sc.hpp).
//
// Channels (texram_chip.json): drf writes one field of a DRF, clut one palette entry (neither
// gives an output); param is a pixel's parameter transactions (the first names the leading
// DRF; one more per takes_coords DRF the chain reaches), a pixel gives its emitted samples
// (last 0) and its colour (last 1); the memory rows are the trilinear unit's with absolute
// addresses; stat holds the sequencer's counters, the memory adds the page model's.
//
// The environment, drawn from the seed and fixed for the block: one chip memory with a few
// maps of random kinds and sizes (the trilinear block's textures) at page-aligned bases without
// overlap, a cube map's six faces, detail maps (000 §9: offset map pairs at some maps' sizes,
// detail mipmaps of 16..256 a side); the chip's one CLUT. The stimulus loads the CLUT, runs
// two pixels on the DRFs as reset and loads a first DRF program; directed items visit every op, an
// emit DRF, every cube face, a 7-step chain, writes presented while a pixel is in flight, lambda at
// its extremes, footprint assembly at every probe limit and both q rules, detail maps at the hard
// lambdas with both combines, the patent's extreme chain, and a link cycle (the step limit, last:
// the flag is sticky); a random run writes a new random valid program (chains of 1..7 DRFs,
// footprint DRFs, texture or reflectance DRFs with detail maps, a cube map in DRF 7 sometimes)
// every few hundred pixels.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/texram_chip/texram_chip_ports.hpp"
#include "blocks/trilinear/texram_setup.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "texram/chip/texram_chip.hpp"
#include "texram/texture.hpp"

TMU_DESCRIBE(texram_chip)

namespace tmu::tb {

// One map of the chip's memory: how it was drawn, its texture and where it sits.
struct ChipMapPlacement {
  TexramSetup setup;
  std::shared_ptr<const texram::TexramTexture> texture;
  uint32_t base = 0;
};

// A detail map's two offset maps (000 §9): luminance maps of plain map `map`'s level-0 size, the
// u map at `base`, the v map right after it (texram::chip::offsets_v_base).
struct ChipOffsetsPlacement {
  size_t map = 0;
  uint32_t base = 0;
  int log2_w = 0, log2_h = 0;
};

// The chip's memory as the block draws it: plain maps, the six faces of a cube map (square,
// of one kind and size), offset map pairs and detail mipmaps.
struct ChipScene {
  std::vector<ChipMapPlacement> maps;
  std::array<ChipMapPlacement, texram::chip::kCubeFaces> faces;
  std::vector<ChipOffsetsPlacement> offsets;
  std::vector<ChipMapPlacement> details;
  std::shared_ptr<const texram::chip::ChipMemory> memory;
  // The same cells as one texture (banks of kBankCells), what the timed runs' memory reads.
  std::shared_ptr<const texram::TexramTexture> image;
  texram::Clut32 clut{};
};
ChipScene draw_chip_scene(uint64_t seed);
// A chip's memory holding `maps` (each at its base) and its CLUT (maps and faces left empty).
ChipScene chip_scene_of(const std::vector<ChipMapPlacement>& maps, const texram::Clut32& clut);

// A DRF program: the seven DRFs and the DRFs a pixel may lead with (every DRF of a chain).
struct ChipProgram {
  texram::chip::DrfFile file{};
  std::vector<int> leads;
};
ChipProgram draw_chip_program(std::mt19937_64& rng, const ChipScene& scene);

// A texture (or reflectance) DRF t with a detail map: t on the plain map of `offsets`, its
// offsets DRF o and detail DRF d (on detail map `detail`), linked t -> o -> d -> 0 for the
// caller to number (t.link and o.link hold 0 until then).
struct ChipDetailDrfs {
  texram::chip::Drf t, o, d;
};
ChipDetailDrfs chip_detail_drfs(std::mt19937_64& rng, const ChipScene& scene, size_t offsets,
                                size_t detail);

class TexramChipBlock : public DescribedBlockOf<TexramChipBlock> {
 public:
  explicit TexramChipBlock(const BlockOptions& options);
  // A chip of a render: its memory and CLUT as the host placed them, `program` its DRFs.
  // setup_items() loads the CLUT and the program; the block's own stimulus stays the drawn one.
  TexramChipBlock(const BlockOptions& options, std::shared_ptr<const ChipScene> scene,
                  const texram::chip::DrfFile& program);

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::string repro_options() const override;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;

  const ChipScene& scene() const { return *scene_; }
  const ChipProgram& first_program() const { return first_; }

 private:
  // The items of one pixel under `program`, led by `lead`, its parameters drawn from rng.
  std::vector<Txn> pixel_items(std::mt19937_64& rng, const ChipProgram& program, int lead) const;
  // The items of a named workload (BlockOptions::chip_workload): its program, then scan lines.
  std::vector<Txn> workload_items(size_t count) const;

  std::shared_ptr<const ChipScene> scene_;
  ChipProgram first_;
  bool drawn_ = true;  // the scene was drawn from the seed (not a render's)
  std::string workload_;
  // cover() sees the items in order: the DRFs as written so far and the pixel in progress.
  mutable size_t cover_next_ = 0;
  mutable texram::chip::DrfFile cover_file_{};
  mutable int cover_pending_ = 0;
  mutable int cover_lead_ = 0;  // the leading DRF of the pixel covered last
};

// ---- Items, for tests and tools ------------------------------------------------------------

Txn chip_drf_item(const texram::chip::DrfWrite& w);
Txn chip_clut_item(uint8_t index, uint32_t rgba);
Txn chip_param_item(const texram::chip::PixelParameter& p);
// Every write of a program (all seven DRFs).
std::vector<Txn> chip_program_items(const texram::chip::DrfFile& file);
texram::chip::PixelParameter chip_parameter(const Txn& item);

}  // namespace tmu::tb
