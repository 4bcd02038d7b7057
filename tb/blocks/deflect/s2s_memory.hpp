// The map memory of the deflection unit's timed runs (hls, rtl): it holds the
// spherical-to-spherical map's blocks (golden/deflect/s2s_map.hpp) and answers the unit's
// block requests on the description's channels (tb/blocks/deflect/deflect.json).
//
// A request (valid for one cycle, no ready: the memory takes every request) names a block;
// the response is valid for one cycle, `latency` cycles after the request plus 0..jitter drawn
// per request, with the block's 16 entries. Between responses the data bus carries random
// bits, so a unit that samples it at the wrong time fails. A request while one is outstanding
// (or in the cycle its predecessor's response arrives), or for a block beyond the map, fails
// the run; the response to a block beyond the map is poison.
//
// Counters: block_fetches (requests), stall_cycles (cycles with a request outstanding, from the
// cycle after the request to its response: the cycles the unit's look-up waited).
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>

#include "deflect/s2s_map.hpp"
#include "harness/environment.hpp"

namespace tmu::tb {

// When the memory answers: `latency` cycles after the request (>= 1: a request sampled at
// cycle c is answered in cycle c + latency), plus 0..jitter cycles drawn per request.
struct S2sMemoryTiming {
  int latency = 4;
  int jitter = 0;
};

class S2sMemory : public Environment {
 public:
  S2sMemory(std::shared_ptr<const deflect::S2sMap> map, S2sMemoryTiming timing, uint64_t seed);

  void drive(EnvPorts& ports) override;
  void sample(const EnvPorts& ports) override;
  bool idle() const override { return !pending_; }
  std::string error() const override { return error_; }
  Counters counters() const override {
    return {{"block_fetches", fetches_}, {"stall_cycles", stall_cycles_}};
  }

  static constexpr uint32_t kPoison = 0x5A5A5A5Au;

 private:
  std::shared_ptr<const deflect::S2sMap> map_;
  S2sMemoryTiming timing_;
  std::mt19937_64 rng_;
  uint64_t cycle_ = 0;
  bool pending_ = false;
  uint32_t pending_block_ = 0;
  uint64_t due_cycle_ = 0;
  uint64_t fetches_ = 0, stall_cycles_ = 0;
  std::string error_;
};

}  // namespace tmu::tb
