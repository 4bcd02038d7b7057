// The TEXRAM mipmap generator as a co-simulation block (`texsim cosim mipgen`): level-0
// texels of whole frames in, bank-cell writes of every level out (000 §12, Fig. 14;
// golden/texram/mipgen_stream.hpp).
//
// Input items: texel, above (the texel above, interlaced field 2; 0 elsewhere), in source
// order. Output transactions: level, x, y (stored coordinates), value, bank, addr.
//
// The environment is the frame format: log2 width and height (0..10, non-square allowed),
// interlaced or not, and the texture's planes (1 or 4) and the plane filled, drawn from the
// seed unless BlockOptions names them. Every run is whole frames of that format.
//
// One input item makes one or more writes (its level-0 texel, its replicas, the higher-level
// texels it completes); the golden engine reports the item behind every write
// (RunResult::output_items), so a mismatch report names the right input item. Coverage is
// counted per input item from the golden model.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"

namespace tmu::tb {

enum MipgenInField { kMipTexel, kMipAbove };
enum MipgenOutField { kMipLevel, kMipX, kMipY, kMipValue, kMipBank, kMipAddr };

class MipgenBlock : public Block {
 public:
  // options.seed draws the format; options.mip_* override its parts.
  explicit MipgenBlock(const BlockOptions& options);
  ~MipgenBlock() override;

  std::string name() const override { return "mipgen"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn&) const override { return true; }
  std::vector<Txn> directed_items() const override;
  // Whole random frames, at least `count` texels.
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;
  std::string repro_options() const override;

  const texram::MipgenConfig& config() const { return config_; }

 private:
  struct CoverState;
  BlockOptions options_;
  texram::MipgenConfig config_;
  mutable std::unique_ptr<CoverState> cover_;  // the golden stream cover() steps through
};

// The format a seed draws: mostly small frames (sides 1..32), often one-texel-wide or -high
// ones, sometimes 1024-texel lines or 128 x 128; interlaced half the time; 1 or 4 planes.
texram::MipgenConfig random_mipgen_config(uint64_t seed);

// One frame's input items in source order (interlaced: fields, with `above`).
std::vector<Txn> mipgen_frame_items(const texram::Level8& level0, bool interlaced);
// A frame in which every 2 x 2 box sum of every level is 2 mod 4 (a rounding tie).
texram::Level8 mipgen_tie_frame(int log2_w, int log2_h);

// Writes as transactions and back.
Txn mipgen_write_txn(const texram::CellWrite& w);
texram::CellWrite mipgen_txn_write(const Txn& t);
// The golden model's writes for `items`; `item_of_write` (when given) receives the input
// item behind each write.
std::vector<texram::CellWrite> mipgen_golden_writes(const texram::MipgenConfig& config,
                                                    const std::vector<Txn>& items,
                                                    std::vector<size_t>* item_of_write = nullptr);

// An engine for `config`: "golden", "hls" or "rtl".
std::unique_ptr<Engine> make_mipgen_engine(const std::string& level,
                                           const texram::MipgenConfig& config);
// The rtl engine for any Verilated model with the generator's ports (tests use a mutant).
template <class Model>
std::unique_ptr<Engine> make_mipgen_rtl_engine(const std::string& name,
                                               const texram::MipgenConfig& config);

}  // namespace tmu::tb

#include "blocks/mipgen_rtl.inl"
