// A block in the described form (docs/harness.md, "Adding a block"): its ports come from its
// description (harness/ports.hpp), and everything generic comes from them: the schemas, the
// port list, which items give outputs, the golden and ideal engines around its Model, the
// rtl engine of any Verilated model with its ports, the hls engine of its SystemC module, the
// Icarus engine, the table of levels and the errors about them. What a block writes is its
// own: the Model (its golden arithmetic), its memory Environment, its directed and random
// items and its coverage cases.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "harness/block.hpp"
#include "harness/environment.hpp"
#include "harness/handshake_driver.hpp"
#include "harness/model.hpp"
#include "harness/ports.hpp"

namespace tmu::tb {

class DescribedBlock : public Block {
 public:
  explicit DescribedBlock(const BlockPorts& ports) : ports_(ports) {}

  const BlockPorts& port_table() const { return ports_; }
  std::string name() const override { return ports_.block(); }
  const Schema& inputs() const override { return ports_.inputs(); }
  const Schema& outputs() const override { return ports_.outputs(); }
  bool produces_output(const Txn& item) const override;
  std::vector<Port> ports() const override;
  std::vector<const Schema*> request_schemas() const override;
  // The engine of a level this block registered; std::invalid_argument naming the levels
  // otherwise.
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> levels() const;

  // The block's own arithmetic: golden is required, ideal optional.
  virtual std::unique_ptr<Model> golden() const = 0;
  virtual std::unique_ptr<Model> ideal() const { return nullptr; }
  // The agents on its memory channels in a timed run; `seed` draws their latencies.
  virtual std::unique_ptr<Environment> environment(uint64_t /*seed*/) const { return nullptr; }
  // What each item gives: one output per Sample (and CombIn) item, none per Write or
  // configuration item; a block with a Stream channel counts by running its golden model.
  ItemPlan plan(const std::vector<Txn>& items) const;

  // The variant its options select (rtl/blocks.cmake: the key of its rtl models; "" the
  // default). The options that select it are the variant's row there, so the reproduce line
  // of a run names them.
  virtual std::string variant() const { return ""; }
  std::string repro_options() const override;

  // A copy that engines keep (they may outlive the block they came from).
  virtual std::shared_ptr<const DescribedBlock> share() const = 0;

  // A level's engine factory: it gets the block it is asked through and keeps a share() of it.
  using EngineFactory = std::function<std::unique_ptr<Engine>(const DescribedBlock&)>;

 protected:
  // Registers a level (the base provides golden, and ideal where ideal() gives a model).
  void add_level(const std::string& level, EngineFactory make);

 private:
  const BlockPorts& ports_;
  std::vector<std::pair<std::string, EngineFactory>> levels_;
};

// Seed of the environment's generator, mixed with RunOptions::stalls.seed.
inline constexpr uint64_t kEnvironmentSeedSalt = 0x7E57'0000'7E1A'0001ull;

// DescribedBlockOf<Derived> implements share().
template <class Derived>
class DescribedBlockOf : public DescribedBlock {
 public:
  using DescribedBlock::DescribedBlock;
  std::shared_ptr<const DescribedBlock> share() const override {
    return std::make_shared<Derived>(static_cast<const Derived&>(*this));
  }
};

// The pieces every block writes for itself, declared in its class as `TMU_BLOCK_PIECES;`
// (harness/block.hpp says what each is): its directed and random items, its golden Model and
// its coverage cases with the predicate that marks them. The optional ones (ideal(),
// environment(), setup_items(), variant()) it declares itself where it has them.
#define TMU_BLOCK_PIECES                                                                         \
  std::vector<Txn> directed_items() const override;                                              \
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;              \
  std::unique_ptr<Model> golden() const override;                                                \
  std::vector<std::string> coverage_cases() const override;                                      \
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output, Coverage& coverage) \
      const override

// The golden or ideal level of a block: a fresh Model per run.
std::unique_ptr<Engine> model_engine(const DescribedBlock& block, const std::string& level);

}  // namespace tmu::tb
