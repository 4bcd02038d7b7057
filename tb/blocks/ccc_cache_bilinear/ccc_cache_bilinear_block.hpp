// The low-cost CCC texture unit as a co-simulation block, `texsim cosim ccc_cache_bilinear`
// (alias ccc-bilinear): a 4-entry cache of decoded CCC blocks with neighbour lookahead
// feeding a bilinear interpolator (000 §4, Figs. 6 and 7; golden/ccc/ccc_cache_bilinear.hpp).
//
// Channels (ccc_cache_bilinear.json): req (u, v SQ16.8) gives one rgb each; clut writes
// an entry (and invalidates the cache); cfg is the texture's size, the lookahead and the seed
// of the texture the memory holds; the memory answers block requests; the statistics are
// hits, misses and prefetches.
//
// The environment: a texture, a .ccc file (--texture) or one drawn from a seed, and the
// lookahead (--no-lookahead, or drawn). The stimulus starts with the configuration item and
// the CLUT load of the seed's texture; a random run draws a new texture and lookahead every
// few thousand items and loads its CLUT, as a driver would between batches (the CLUT load
// also invalidates the cache, which a new size needs).
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_ports.hpp"
#include "blocks/registry.hpp"
#include "ccc/ccc_texture.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(ccc_cache_bilinear)

namespace tmu::tb {

class CccCacheBilinearBlock : public DescribedBlockOf<CccCacheBilinearBlock> {
 public:
  // options.texture: a .ccc file (empty: random textures drawn from options.seed);
  // options.lookahead: the neighbour prefetch (unset: drawn per batch, on for the first).
  explicit CccCacheBilinearBlock(const BlockOptions& options);
  // On a given texture (sides 1..4096), e.g. a scene material's.
  CccCacheBilinearBlock(const BlockOptions& options, std::shared_ptr<const ccc::Texture> texture);

  std::vector<Txn> setup_items() const override;
  TMU_BLOCK_PIECES;
  std::unique_ptr<Environment> environment(uint64_t seed) const override;
  std::string repro_options() const override;

  // The first environment's texture (the given one, or the seed's).
  const std::shared_ptr<const ccc::Texture>& texture() const { return first_; }
  // The configuration item of a texture (texture_seed names a random one's content) and its
  // CLUT load: what a driver writes before sampling it.
  Txn config_item(const ccc::Texture& texture, bool lookahead, uint32_t texture_seed) const;
  std::vector<Txn> texture_load(const ccc::Texture& texture, bool lookahead,
                                uint32_t texture_seed) const;
  // The texture a configuration item names: the given one, or the random one of its size and
  // seed.
  std::shared_ptr<const ccc::Texture> texture_of(const Txn& cfg) const;

 private:
  BlockOptions options_;
  std::shared_ptr<const ccc::Texture> fixed_;  // given (a file, a scene's); else random ones
  std::shared_ptr<const ccc::Texture> first_;
  uint32_t first_seed_ = 0;
  // cover() sees the items in order: the texture size in effect.
  mutable size_t cover_next_ = 0;
  mutable uint32_t cover_w_ = 1, cover_h_ = 1;
};

// A random texture of the given size (1..4096 a side): random CLUT and block words from seed.
ccc::Texture random_bilinear_texture(uint32_t width, uint32_t height, uint64_t seed);

// Item constructors, for tests and tools. Coordinates are raw SQ16.8 (texels * 256).
Txn bilinear_sample_item(int32_t u_raw, int32_t v_raw);
Txn bilinear_clut_item(uint8_t index, uint32_t rgb);
// Every pixel of `tex` resampled to out_w x out_h in raster order, pixel centres mapped onto
// texel space: what a rasterizer sends for a screen-aligned rectangle.
std::vector<Txn> bilinear_resample_items(const ccc::Texture& tex, uint32_t out_w, uint32_t out_h);
// The raw SQ16.8 coordinate of a sample item's field (sign-extended).
int32_t bilinear_coord(uint64_t field);

}  // namespace tmu::tb
