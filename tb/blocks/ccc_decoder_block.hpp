// The CCC decoder as a co-simulation block (`texsim cosim ccc`).
//
// Input items: op 0 = decode (block, texel), op 1 = CLUT write (clut_addr, clut_rgb).
// Output: the decoded texel's rgb, one per decode.
#pragma once

#include <memory>

#include "ccc/ccc_texture.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

enum CccDecoderField { kDecOp, kDecBlock, kDecTexel, kDecClutAddr, kDecClutRgb };
enum CccDecoderOp : uint64_t { kOpDecode = 0, kOpClutWrite = 1 };

class CccDecoderBlock : public Block {
 public:
  explicit CccDecoderBlock(uint64_t seed);

  std::string name() const override { return "ccc"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn& item) const override { return item.f[kDecOp] == kOpDecode; }
  std::vector<Txn> setup_items() const override;
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;

 private:
  uint64_t seed_;
};

// Item constructors, for tests and tools.
Txn decode_item(uint32_t block_word, unsigned texel);
Txn clut_write_item(uint8_t index, uint32_t rgb);

// Decodes every texel of `tex` through a decoder engine (CLUT load, then the texels in
// row-major order, no stalls). `run` receives the engine's run (timing, errors).
ImageRgb8 decode_with_engine(const ccc::Texture& tex, Engine& engine, RunResult* run = nullptr);

// The rtl engine for any Verilated model with the decoder's ports (tests use a mutant).
template <class Model>
std::unique_ptr<Engine> make_ccc_decoder_rtl_engine(const std::string& name);

}  // namespace tmu::tb

#include "blocks/ccc_decoder_rtl.inl"
