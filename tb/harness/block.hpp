// What a block provides to plug into the co-simulation harness: its transaction schemas,
// stimulus (setup, directed, random), its engines, its named coverage cases and its ports.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "harness/engine.hpp"
#include "harness/txn.hpp"

namespace tmu::tb {

using Coverage = std::map<std::string, uint64_t>;

// A top-level port, for the GTKWave save file of a mismatch waveform.
struct Port {
  std::string name;
  int width = 1;
  bool is_signed = false;
};

class Block {
 public:
  virtual ~Block() = default;

  virtual std::string name() const = 0;
  virtual const Schema& inputs() const = 0;
  virtual const Schema& outputs() const = 0;
  // Whether an input item produces one output transaction (a CLUT write produces none).
  virtual bool produces_output(const Txn& item) const = 0;

  // Items that bring the block into a defined state before the stimulus (e.g. a CLUT load).
  virtual std::vector<Txn> setup_items() const { return {}; }
  // Hand-written corner cases, run before the random items.
  virtual std::vector<Txn> directed_items() const = 0;
  virtual std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const = 0;

  // level: "golden", "hls" or "rtl".
  virtual std::unique_ptr<Engine> engine(const std::string& level) const = 0;

  // Every named case, in print order; cover() counts the ones items[index] (which produced
  // `output`, its first output if it made several) exercises, looking back at earlier items
  // where a case needs history. It is called once per item that produced output, in order.
  virtual std::vector<std::string> coverage_cases() const = 0;
  virtual void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
                     Coverage& coverage) const = 0;

  virtual std::vector<Port> ports() const = 0;
  // The schema of each memory request channel whose requests the scoreboard compares.
  virtual std::vector<const Schema*> request_schemas() const { return {}; }
  // Options of `texsim cosim` that recreate this block's environment (e.g. its texture).
  virtual std::string repro_options() const { return ""; }
};

}  // namespace tmu::tb
