// The normal encoder as a co-simulation block (`texsim cosim normal-encoder`): an
// unnormalised Cartesian normal to its angles on the sphere grid (001 §4.1, eq. 12-16;
// golden/deflect/normal_encoder.hpp).
//
// Input items: x, y, z (UnitComp SQ2.14). Output: phi (SpherePhi) and theta (SphereTheta).
// The encoder's configuration is BlockOptions::encoder (grid A = 9, the ports' width); golden
// and hls take any seed and table widths, the rtl engine the Verilated ones (rtl/
// CMakeLists.txt: the default and the paper's linear index E = 1, M = 7).
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "deflect/normal_encoder.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

enum NormalEncoderField { kEncX, kEncY, kEncZ };
enum NormalEncoderOutField { kEncPhi, kEncTheta };

class NormalEncoderBlock : public Block {
 public:
  explicit NormalEncoderBlock(const BlockOptions& options);

  std::string name() const override { return "normal-encoder"; }
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
  std::string repro_options() const override;

  const deflect::EncoderConfig& config() const { return encoder_.config(); }

 private:
  deflect::NormalEncoder encoder_;
  // cover() collects the table indices seen so far (it sees every item in order); the sets of
  // angle-table indices some ratio reaches.
  std::set<uint32_t> reachable_angle_;
  mutable size_t cover_next_ = 0;
  mutable std::set<uint32_t> seen_angle_[2], seen_seed_[2];  // [0] phi, [1] theta
};

// An item from the components' values.
Txn normal_item(int16_t x, int16_t y, int16_t z);
int16_t normal_x(const Txn& item);
int16_t normal_y(const Txn& item);
int16_t normal_z(const Txn& item);

// The divider's seed-table index for a denominator (golden divide_ratio's i; 0 for den = 0).
uint32_t encoder_seed_index(uint32_t den, int seed_bits);
// Every angle-table index some ratio t = 1 .. 2^16 reads (t = 0 reads none; for e < E - 1 the
// index's top two mantissa bits are never both zero: those entries are dead).
std::set<uint32_t> reachable_angle_indices(const deflect::EncoderConfig& config);

// The rtl engine for any Verilated model with the encoder's ports (tests use mutants and the
// E = 1, M = 7 variant).
template <class Model>
std::unique_ptr<Engine> make_normal_encoder_rtl_engine(const std::string& name);

}  // namespace tmu::tb

#include "blocks/normal_encoder_rtl.inl"
