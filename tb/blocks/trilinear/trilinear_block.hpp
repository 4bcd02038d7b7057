// The TEXRAM trilinear unit as a co-simulation block, `texsim cosim trilinear`: levels and
// weights from lambda, border operators per axis, one access of the eight banks per byte
// plane, the five texel configurations, the exact blend and eq. 5 (000 §2, §5, §6;
// golden/texram/trilinear.hpp, rtl/texram/tmu_trilinear.sv, hls/texram/trilinear_sc.hpp).
//
// Channels (trilinear.json): req (u, v SQ16.8 texels of level 0, lambda SQ6.8, the shade
// I_d) gives one rgba each; clut writes an entry; cfg is the unit's configuration and the
// texture the memory holds (its kind and size are ports; its content and seed are not); the
// memory answers every access of the eight banks with the page model's timing (texram_memory.hpp),
// and golden predicts every access, in order, with the page model's counters.
//
// The environment: the first is drawn from the seed (texram_setup.hpp; BlockOptions::tri_*
// fix what they set), or given (an image file, a scene's texture). The stimulus starts with its
// configuration item and, for index and CCC textures, its CLUT load; the directed items then
// tour every texel kind, filter, border mode and combine (the options leaving them free); a
// random run draws a new environment every few thousand items and loads its CLUT, as a driver
// would between batches. The widths (S, W, L) are the unit's parameters: rtl variants in
// rtl/blocks.cmake.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "blocks/trilinear/texram_setup.hpp"
#include "blocks/trilinear/texram_textures.hpp"
#include "blocks/trilinear/trilinear_ports.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"
#include "texram/page_model.hpp"
#include "texram/texture.hpp"

TMU_DESCRIBE(trilinear)

namespace tmu::tb {

// A given texture and how the unit samples it (a scene's material, a tool's texture).
struct TrilinearEnv {
  std::shared_ptr<const texram::TexramTexture> texture;
  texram::SamplerConfig config;  // config.widths: the unit's
  std::string content;           // what the texture holds, for reports
};

class TrilinearBlock : public DescribedBlockOf<TrilinearBlock> {
 public:
  // The environments drawn from options.seed (options.tri_image: that image in every kind).
  // Throws InputError for an unreadable image or one whose sides are not powers of two up to
  // 1024, and std::invalid_argument for a bad option.
  explicit TrilinearBlock(const BlockOptions& options);
  // On a given texture: its kind and size in every environment.
  TrilinearBlock(const BlockOptions& options, TrilinearEnv env);

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::unique_ptr<Model> ideal() const override;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;
  std::string variant() const override;
  std::string repro_options() const override;

  // The first environment, and one line describing it.
  const TexramSetup& first() const { return first_; }
  std::string describe() const;
  const std::shared_ptr<const TexramTextures>& textures() const { return textures_; }
  // The configuration item of a setup and, for index and CCC textures, its texture's CLUT
  // load: what a driver writes before sampling it.
  std::vector<Txn> texture_load(const TexramSetup& setup) const;

 private:
  // The environments the directed items visit after the first (options.tri_* fixed).
  std::vector<TexramSetup> tour() const;
  // Whether the directed items tour environments (not when a given texture fixes them).
  bool tours() const;
  std::vector<Txn> directed_samples(const TexramSetup& setup) const;
  std::vector<Txn> directed_sphere_samples(const TexramSetup& setup) const;

  BlockOptions options_;
  std::shared_ptr<const TexramTextures> textures_;
  TexramSetup first_;
  // cover() sees the items in order: the setup in effect and the pages of the accesses so far.
  mutable size_t cover_next_ = 0;
  mutable TexramSetup cover_setup_;
  mutable texram::PageModel cover_pages_;
};

// ---- Items, for tests and tools: raw port values (SQ16.8 and SQ6.8: value * 256) ----------

Txn trilinear_sample_item(int32_t u_raw, int32_t v_raw, int32_t lambda_raw, uint32_t shade = 0);
Txn trilinear_clut_item(uint8_t index, uint32_t rgba);
// The 256 CLUT writes of a texture's CLUT.
std::vector<Txn> trilinear_clut_load(const texram::TexramTexture& texture);
// The raw values of a sample item's fields (sign-extended), and its request.
int32_t trilinear_coord(uint64_t field);
int32_t trilinear_lambda(uint64_t field);
texram::Request trilinear_request(const Txn& item);

// The configuration item of a setup, and the setup of one (config.widths = `widths`). The
// footprint block's configuration begins with the same fields in the same slots: these write and
// read those (texram.json's texram_cfg), config.addressing stays texel.
Txn texram_cfg_item(const TexramSetup& setup);
TexramSetup texram_setup_of(const Txn& cfg, const texram::Widths& widths);
// The trilinear unit's own: the same and its field addressing.
Txn trilinear_cfg_item(const TexramSetup& setup);
TexramSetup trilinear_setup_of(const Txn& cfg, const texram::Widths& widths);

}  // namespace tmu::tb
