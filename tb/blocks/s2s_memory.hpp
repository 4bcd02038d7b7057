// The environment of the deflection unit's hls and rtl benches (`texsim cosim deflect`): the
// map memory that holds the spherical-to-spherical map's blocks, and a monitor of the
// results' access codes. Both report the counters the golden model predicts.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "deflect/s2s_map.hpp"
#include "harness/engine.hpp"

namespace tmu::tb {

// When the memory answers: `latency` cycles after the request (>= 1: a request sampled at
// cycle c is answered in cycle c + latency), plus 0..jitter cycles drawn per request.
struct S2sMemoryTiming {
  int latency = 4;
  int jitter = 0;
};

// The map memory. A request (valid for one cycle, no ready: the memory takes every request)
// names a block; the response is valid for one cycle with the block's 16 entries, entry o at
// bits EntryW o. Between responses the data bus carries random bits, so a unit that samples
// it at the wrong time fails. Protocol errors (a request while one is outstanding, a block
// beyond the map) fail the run; the response to a block beyond the map is poison.
//
// Counters: block_fetches (requests), stall_cycles (cycles with a request outstanding, from
// the cycle after the request to its response: the cycles the unit's look-up waited).
class S2sMemory {
 public:
  S2sMemory(std::shared_ptr<const deflect::S2sMap> map, S2sMemoryTiming timing, uint64_t seed);

  struct Inputs {
    bool resp_valid = false;
    std::vector<uint32_t> resp_words;  // the block, 32 bits per word, least significant first
  };
  // The memory's side of the ports for this cycle (the same values until sample()).
  const Inputs& drive();
  // The unit's request as seen before the edge; ends the cycle.
  void sample(bool req_valid, uint32_t block);

  static constexpr uint32_t kPoison = 0x5A5A5A5Au;
  const std::string& error() const { return error_; }
  Counters counters() const {
    return {{"block_fetches", fetches_}, {"stall_cycles", stall_cycles_}};
  }
  int words() const { return static_cast<int>(now_.resp_words.size()); }

 private:
  std::shared_ptr<const deflect::S2sMap> map_;
  S2sMemoryTiming timing_;
  std::mt19937_64 rng_;
  uint64_t cycle_ = 0;
  bool drawn_ = false;
  Inputs now_;
  bool pending_ = false;
  uint32_t pending_block_ = 0;
  uint64_t due_cycle_ = 0;
  uint64_t fetches_ = 0, stall_cycles_ = 0;
  std::string error_;
};

// The block's 16 entries packed as the map memory's response carries them.
std::vector<uint32_t> pack_s2s_block(const deflect::S2sMap& map, uint32_t block);

// Counts the results' access codes as they leave the unit (an output handshake seen before
// the edge): hits, misses, bypasses, like the golden model's counters.
class MapAccessMonitor {
 public:
  void sample(bool out_fire, uint64_t access);
  Counters counters() const {
    return {{"hits", hits_}, {"misses", misses_}, {"bypasses", bypasses_}};
  }

 private:
  uint64_t hits_ = 0, misses_ = 0, bypasses_ = 0;
};

// Every counter of a bench: the monitor's, then the memory's.
inline Counters deflect_bench_counters(const MapAccessMonitor& monitor, const S2sMemory& memory) {
  Counters c = monitor.counters();
  for (const auto& kv : memory.counters()) c.push_back(kv);
  return c;
}

// Salt of the memory's generator, mixed with RunOptions::stalls.seed.
inline constexpr uint64_t kS2sMemorySeedSalt = 0x7E57'0000'5255'0001ull;

}  // namespace tmu::tb
