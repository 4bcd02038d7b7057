// The specular combine as a co-simulation block (`texsim cosim specular-combine`): the
// diffusely shaded texture colour plus the reflectance times the environment or specular
// sample, per channel saturated at 255, alpha from the diffuse colour (000 §7 eq. 6, §8 eq. 7;
// golden/texram/specular_combine.hpp).
//
// Input items: diffuse (D), specular (E), reflectance (R), each Rgba8888. Output: colour (C),
// Rgba8888.
#pragma once

#include <bitset>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

enum SpecularCombineField { kSpcDiffuse, kSpcSpecular, kSpcReflectance };
enum SpecularCombineOutField { kSpcColour };

class SpecularCombineBlock : public Block {
 public:
  std::string name() const override { return "specular-combine"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn&) const override { return true; }
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;

 private:
  // cover() sees every item in order; the (e, r) pairs seen so far in R, G, B (index e 256 + r).
  mutable size_t cover_next_ = 0;
  mutable std::bitset<65536> seen_pairs_[3];
  mutable size_t seen_count_[3] = {};
};

// An item from the three colours (0xRRGGBBAA each); the renderer builds its items with it.
Txn specular_combine_item(uint32_t diffuse, uint32_t specular, uint32_t reflectance);

// The rtl engine for any Verilated model with the block's ports (tests use the mutants).
template <class Model>
std::unique_ptr<Engine> make_specular_combine_rtl_engine(const std::string& name);

}  // namespace tmu::tb

#include "blocks/specular_combine_rtl.inl"
