// The clip-map's eight banks in a timed run (hls, rtl): the TEXRAM memory of the sampling path
// (blocks/trilinear/texram_memory.hpp, the same page model and timing) with writes. An accepted
// access takes the page model's periods (ready low for the extra period of a fault); a read is
// answered in order the cycle it completes, with random bytes in the banks it does not read; a
// write (we) changes the cells of its enabled banks and is not answered. A configuration item
// clears the banks to the new clip-map's size (zeros: the load port fills them). An access
// that enables no bank, or a cell beyond a bank, fails the run.
#pragma once

#include <cstdint>
#include <deque>
#include <random>
#include <string>

#include "clipmap/clipmap.hpp"
#include "harness/environment.hpp"
#include "texram/page_model.hpp"

namespace tmu::tb {

// The memory port's request of an access (golden's prediction and the env's reading of it).
Txn clip_access_request(const clipmap::BankAccess& access, bool write, int plane);
clipmap::BankAccess clip_access_of(const Txn& request, bool* write);

class ClipMemory : public Environment {
 public:
  explicit ClipMemory(uint64_t seed);

  void configure(const Txn& cfg) override;
  void drive(EnvPorts& ports) override;
  void sample(const EnvPorts& ports) override;
  bool idle() const override { return responses_.empty(); }
  std::string error() const override { return error_; }
  Counters counters() const override;

 private:
  struct Response {
    uint64_t due_cycle;
    uint64_t data;  // bank b's byte at bits 8b + 7 .. 8b
  };
  texram::BankImage banks_;
  std::mt19937_64 rng_;
  texram::PageModel pages_;
  uint64_t cycle_ = 0;
  uint64_t busy_until_ = 0;
  bool drawn_ = false;
  bool ready_ = false, valid_ = false;
  uint64_t data_ = 0;
  std::deque<Response> responses_;
  std::string error_;
};

}  // namespace tmu::tb
