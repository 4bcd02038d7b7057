// The shared memory of the video unit's timed runs (hls, rtl): the eight banks the unit writes
// its row buffers to and reads the line above from (tb/blocks/video_unit/video_unit.json).
//
// A request (valid for one cycle, no ready: the memory takes every request) is a masked write
// of a word of 8 cells (kVideoUnitWordCells; a row is one or more), applied at once, or a read
// of a word, answered `latency` cycles after the
// request plus 0..jitter drawn per read, with the row's cells as the writes before it left
// them. Between responses the data bus carries random bits, so a unit that samples it at the
// wrong time fails. A configuration item with a new format or new buffer bases starts a new
// video map: the memory is cleared, as the golden model's VideoMap starts with its banks at 0.
// A cell beyond the bank's 2^21 fails the run.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include "blocks/video_unit/video_unit_block.hpp"
#include "harness/environment.hpp"

namespace tmu::tb {

class VideoMemory : public Environment {
 public:
  VideoMemory(int latency, int jitter, uint64_t seed);

  void configure(const Txn& cfg) override;
  void drive(EnvPorts& ports) override;
  void sample(const EnvPorts& ports) override;
  bool idle() const override { return responses_.empty(); }
  std::string error() const override { return error_; }

 private:
  struct Response {
    uint64_t due_cycle;
    std::array<uint8_t, kVideoUnitWordCells> cells;
  };
  uint8_t cell(unsigned bank, uint32_t address) const;

  int latency_, jitter_;
  std::mt19937_64 rng_;
  std::array<std::vector<uint8_t>, 8> banks_;  // grown as written; unwritten cells are 0
  Txn map_;                                    // the format and bases of the video map
  uint64_t cycle_ = 0;
  std::deque<Response> responses_;
  std::string error_;
};

}  // namespace tmu::tb
