// The TEXRAM's eight banks as the sampling path's blocks see them (trilinear, footprint): the
// accesses a sample makes, each as the request the unit shows on its memory port, the memory's
// counters, and the memory of the timed runs (hls, rtl).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "harness/environment.hpp"
#include "texram/page_model.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::tb {

// The cell read in each bank (none where the bank is not read).
using BankCells = std::array<std::optional<uint32_t>, 8>;

// One access of a sample: byte plane `plane` of its taps' cells.
struct BankAccess {
  BankCells cells;  // plane-0 address + plane
  int plane = 0;
};
// The accesses of a sample, in the order the unit makes them: one per byte plane (plane p at
// address + p); none when it reads nothing (every tap outside).
std::vector<BankAccess> sample_accesses(const texram::SamplePlan& plan);

// The request of an access on the mem_req port (slots of desc::trilinear, which footprint
// shares): en<b> for each bank read, addr<b> its cell; a bank not read shows address 0 + plane,
// as the RTL drives it (its plane-0 address register is 0 there).
Txn access_request(const BankAccess& access);

// The memory's counters from the page model (000 §5): accesses, bank_reads, page_faults,
// slow_accesses.
Counters page_counters(const texram::PageStats& stats);

// The eight banks in a timed run. An accepted access takes the page model's periods: ready is
// low for the extra period of a fault, and the response (every bank's byte; random bytes in the
// banks not read) is valid the cycle the access completes: the cycle after it was accepted on a
// page hit, two cycles after on a fault. Responses come in order. A cell beyond a bank fails the
// run, and so does an access that reads no bank unless `empty_accesses` (the volume unit's fixed
// schedule: an access whose voxels are all outside the volume still takes its period and is
// one access of the page model; its response is garbage). A configuration item loads the
// texture it names into the banks (the open pages stay open: the page model runs on across
// textures, as golden's). `open_pages`: the pages open at the start (a run that continues
// another's: a render's volume unit in pieces); by default none.
class TexramMemory : public Environment {
 public:
  using TextureOf = std::function<std::shared_ptr<const texram::TexramTexture>(const Txn& cfg)>;
  TexramMemory(TextureOf texture_of, uint64_t seed, bool empty_accesses = false,
               const texram::OpenPages& open_pages = {});

  void configure(const Txn& cfg) override { texture_ = texture_of_(cfg); }
  void drive(EnvPorts& ports) override;
  void sample(const EnvPorts& ports) override;
  bool idle() const override { return responses_.empty(); }
  std::string error() const override { return error_; }
  Counters counters() const override { return page_counters(pages_.stats()); }

  static constexpr uint8_t kPoison = 0xA5;

 private:
  struct Response {
    uint64_t due_cycle;
    uint64_t data;  // bank b's byte at bits 8b + 7 .. 8b
  };
  TextureOf texture_of_;
  bool empty_accesses_ = false;
  std::shared_ptr<const texram::TexramTexture> texture_;
  std::mt19937_64 rng_;
  texram::PageModel pages_;
  uint64_t cycle_ = 0;
  uint64_t busy_until_ = 0;  // ready again from this cycle
  // This cycle's values, drawn at the first drive() of the cycle (reset cycles drive without
  // sampling: they see the same values).
  bool drawn_ = false;
  bool ready_ = false, valid_ = false;
  uint64_t data_ = 0;
  std::deque<Response> responses_;
  std::string error_;
};

}  // namespace tmu::tb
