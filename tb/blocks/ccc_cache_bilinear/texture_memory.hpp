// The texture memory of the low-cost CCC unit's timed runs (hls, rtl): one outstanding block
// request; a request is accepted with probability 80 % in a cycle, and its response comes
// 1..6 cycles later with the texture's block word (garbage on the bus otherwise). A request
// beyond the texture, or a second one while one is outstanding, fails the run. A
// configuration item gives it the texture it names.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>

#include "ccc/ccc_texture.hpp"
#include "harness/environment.hpp"

namespace tmu::tb {

class TextureMemory : public Environment {
 public:
  using TextureOf = std::function<std::shared_ptr<const ccc::Texture>(const Txn& cfg)>;
  TextureMemory(TextureOf texture_of, uint64_t seed);

  void configure(const Txn& cfg) override { texture_ = texture_of_(cfg); }
  void drive(EnvPorts& ports) override;
  void sample(const EnvPorts& ports) override;
  bool idle() const override { return !pending_; }
  std::string error() const override { return error_; }

  static constexpr uint32_t kPoison = 0xDEADBEEFu;

 private:
  TextureOf texture_of_;
  std::shared_ptr<const ccc::Texture> texture_;
  std::mt19937_64 rng_;
  uint64_t cycle_ = 0;
  bool pending_ = false;
  uint32_t pending_word_ = 0;
  uint64_t due_cycle_ = 0;
  std::string error_;
};

}  // namespace tmu::tb
