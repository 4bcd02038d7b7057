// A block's golden (or ideal) arithmetic as the harness runs it: item by item, in order, with
// its outputs and the memory requests it predicts; the engine around it (timing, reserving,
// recording which item made which output) is written once here.
#pragma once

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/engine.hpp"

namespace tmu::tb {

// Where a model's step puts what it makes.
class Sink {
 public:
  explicit Sink(RunResult& result) : r_(result) {}
  void output(const Txn& t) {
    r_.outputs.push_back(t);
    r_.output_items.push_back(item_);
  }
  // A request on memory request channel r (in the order of BlockPorts::request_channels()).
  void request(size_t r, const Txn& t) {
    if (r_.requests.size() <= r) r_.requests.resize(r + 1);
    r_.requests[r].push_back(t);
  }
  void set_item(size_t item) { item_ = item; }

 private:
  RunResult& r_;
  size_t item_ = 0;
};

class Model {
 public:
  virtual ~Model() = default;
  // A configuration item (blocks with Cfg or Env rows).
  virtual void configure(const Txn&) {}
  // One stimulus item.
  virtual void step(const Txn& item, Sink& sink) = 0;
  // The statistics at the end (the stat ports and the environment's counters it predicts).
  virtual Counters counters() const { return {}; }
};

// Runs a fresh model over the items; untimed (every output at cycle 0). A model that throws
// fails the run with its message.
class ModelEngine : public Engine {
 public:
  using Factory = std::function<std::unique_ptr<Model>()>;
  using IsConfig = std::function<bool(const Txn&)>;
  ModelEngine(std::string name, Factory make, IsConfig is_config, size_t requests)
      : name_(std::move(name)),
        make_(std::move(make)),
        is_config_(std::move(is_config)),
        requests_(requests) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(items.size());
    r.output_items.reserve(items.size());
    r.requests.resize(requests_);
    Sink sink(r);
    const auto start = std::chrono::steady_clock::now();
    try {
      std::unique_ptr<Model> model = make_();
      for (size_t i = 0; i < items.size(); ++i) {
        sink.set_item(i);
        if (is_config_(items[i])) {
          model->configure(items[i]);
        } else {
          model->step(items[i], sink);
        }
      }
      r.counters = model->counters();
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    return r;
  }

 private:
  std::string name_;
  Factory make_;
  IsConfig is_config_;
  size_t requests_;
};

}  // namespace tmu::tb
