// The low-cost CCC texture unit as a co-simulation block (`texsim cosim ccc-bilinear`):
// a 4-entry cache of decoded CCC blocks with neighbour lookahead feeding a bilinear
// interpolator (000 §4, Figs. 6 and 7; golden/ccc/ccc_cache_bilinear.hpp).
//
// Input items: op 0 = sample (u, v: SQ16.8 texels), op 1 = CLUT write (clut_addr, clut_rgb).
// Output: the bilinear sample's rgb, one per sample. Counters: hits, misses, prefetches.
//
// The block's environment is a texture: a .ccc file, or one drawn from the seed. Its blocks
// are served to the hls and rtl models by TextureMemory, a memory with random ready and
// latency; the golden model reads them directly.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>

#include "blocks/registry.hpp"
#include "ccc/ccc_texture.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

enum CccBilinearField { kBilOp, kBilU, kBilV, kBilClutAddr, kBilClutRgb };
enum CccBilinearOp : uint64_t { kBilOpSample = 0, kBilOpClutWrite = 1 };

class CccBilinearBlock : public Block {
 public:
  // options.texture: a .ccc file (empty: a random texture drawn from options.seed);
  // options.lookahead: the unit's neighbour prefetch.
  explicit CccBilinearBlock(const BlockOptions& options);
  // On a given texture (sides 1..4096), e.g. a scene material's.
  CccBilinearBlock(const BlockOptions& options, std::shared_ptr<const ccc::Texture> texture);

  std::string name() const override { return "ccc-bilinear"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn& item) const override { return item.f[kBilOp] == kBilOpSample; }
  std::vector<Txn> setup_items() const override;
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;
  std::string repro_options() const override;

  const std::shared_ptr<const ccc::Texture>& texture() const { return texture_; }
  bool lookahead() const { return lookahead_; }

 private:
  BlockOptions options_;
  std::shared_ptr<const ccc::Texture> texture_;
  bool lookahead_;
};

// A random texture: sides 1..80 texels (now and then 81..300, or 1), random CLUT and block
// words. The same seed always gives the same texture.
ccc::Texture random_bilinear_texture(uint64_t seed);

// Item constructors, for tests and tools. Coordinates are raw SQ16.8 (texels * 256).
Txn bilinear_sample_item(int32_t u_raw, int32_t v_raw);
Txn bilinear_clut_item(uint8_t index, uint32_t rgb);
// The 256 CLUT writes that load a texture's colours.
std::vector<Txn> bilinear_clut_load(const ccc::Texture& tex);
// The CLUT load, then every pixel of `tex` resampled to out_w x out_h in raster order, pixel
// centres mapped onto texel space: what a rasterizer sends for a screen-aligned rectangle.
std::vector<Txn> bilinear_resample_items(const ccc::Texture& tex, uint32_t out_w, uint32_t out_h);
// The raw SQ16.8 coordinate of a sample item's field (sign-extended).
int32_t bilinear_coord(uint64_t field);

// The texture memory of the hls and rtl benches: one outstanding request; the request is
// accepted with probability 80 % in a cycle, the response comes 1..6 cycles later with the
// texture's block word. A request beyond the texture gets a poison word and fails the run.
class TextureMemory {
 public:
  TextureMemory(std::shared_ptr<const ccc::Texture> texture, uint64_t seed);

  struct Inputs {
    bool req_ready = false;
    bool resp_valid = false;
    uint32_t resp_block = 0;
  };
  // The memory's side of the ports for this cycle (the same values until sample()).
  Inputs drive();
  // The unit's request as seen before the edge; ends the cycle.
  void sample(bool req_valid, uint32_t address);

  static constexpr uint32_t kPoison = 0xDEADBEEFu;
  // The first protocol or address error the memory saw (empty if none).
  const std::string& error() const { return error_; }
  uint64_t reads() const { return reads_; }

 private:
  uint64_t draw() { return rng_(); }

  std::shared_ptr<const ccc::Texture> texture_;
  std::mt19937_64 rng_;
  uint64_t cycle_ = 0;
  bool drawn_ = false;
  Inputs now_;
  bool pending_ = false;
  uint32_t pending_word_ = 0;
  uint64_t due_cycle_ = 0;
  uint64_t reads_ = 0;
  std::string error_;
};

// Salt of the memory's generator, mixed with RunOptions::stalls.seed.
inline constexpr uint64_t kTextureMemorySeedSalt = 0x7E57'0000'B10C'0001ull;

// The rtl engine for any Verilated model with the unit's ports (tests use mutants).
template <class Model>
std::unique_ptr<Engine> make_ccc_bilinear_rtl_engine(const std::string& name,
                                                     std::shared_ptr<const ccc::Texture> texture,
                                                     bool lookahead);

}  // namespace tmu::tb

#include "blocks/ccc_bilinear_rtl.inl"
