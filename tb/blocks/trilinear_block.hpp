// The TEXRAM trilinear unit as a co-simulation block (`texsim cosim trilinear`): levels and
// weights from lambda, border operators per axis, one access of the eight banks per byte
// plane, the five texel configurations, the exact blend and eq. 5 (000 §2, §5, §6;
// golden/texram/trilinear.hpp).
//
// Input items: op 0 = sample (u, v: SQ16.8 texels of level 0; lambda: SQ6.8; shade: I_d,
// RGBA8888), op 1 = CLUT write (clut_addr, clut_rgba). Output: the sample's rgba, one per
// sample. Counters (the memory's view of the unit): accesses, bank_reads, page_faults,
// slow_accesses (texram::PageModel), and address_hash, a hash of every access's banks and
// addresses in order, so a read of a wrong cell fails the comparison even when the bytes
// there happen to give the right colour.
//
// The block's environment is a texture in the TEXRAM's banks and the unit's configuration,
// drawn from the seed (kind, size, content, filter, borders, combine) unless BlockOptions
// overrides them. The hls and rtl models read the banks through TexramMemory, whose timing is
// the page model's: an access takes one period on a page hit and two on a fault.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include "blocks/registry.hpp"
#include "formats/formats.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"
#include "texram/page_model.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"

namespace tmu::tb {

enum TrilinearField { kTriOp, kTriU, kTriV, kTriLambda, kTriShade, kTriClutAddr, kTriClutRgba };
enum TrilinearOp : uint64_t { kTriOpSample = 0, kTriOpClutWrite = 1 };

// What the unit samples and how.
struct TrilinearEnv {
  std::shared_ptr<const texram::TexramTexture> texture;
  texram::SamplerConfig config;
  std::string content;  // what the texture holds ("smooth field", "random bytes", a file)
};

// The environment of `options`: every field of BlockOptions::tri_* that is set, the rest drawn
// from options.seed (the same seed always gives the same environment). Throws InputError for
// an unreadable image or one whose sides are not powers of two up to 1024, and
// std::invalid_argument for a bad name or width.
TrilinearEnv make_trilinear_env(const BlockOptions& options);

class TrilinearBlock : public Block {
 public:
  explicit TrilinearBlock(const BlockOptions& options);
  TrilinearBlock(const BlockOptions& options, TrilinearEnv env);

  std::string name() const override { return "trilinear"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn& item) const override { return item.f[kTriOp] == kTriOpSample; }
  std::vector<Txn> setup_items() const override;
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;
  std::string repro_options() const override;

  const TrilinearEnv& env() const { return env_; }
  // One line: kind, size, content, filter, borders, combine, widths.
  std::string describe() const;

 private:
  BlockOptions options_;
  TrilinearEnv env_;
  // cover() replays the page model over the samples seen so far (page-fault coverage).
  struct CoverState {
    const std::vector<Txn>* items = nullptr;
    size_t next = 0;
    texram::PageModel pages;
  };
  mutable CoverState cover_state_;
};

// Item constructors, for tests and tools. Coordinates and lambda are raw (value * 256).
Txn trilinear_sample_item(int32_t u_raw, int32_t v_raw, int32_t lambda_raw, uint32_t shade = 0);
Txn trilinear_clut_item(uint8_t index, uint32_t rgba);
// The 256 CLUT writes that load a texture's CLUT.
std::vector<Txn> trilinear_clut_load(const texram::TexramTexture& texture);
// The raw values of a sample item's fields (sign-extended).
int32_t trilinear_coord(uint64_t field);
int32_t trilinear_lambda(uint64_t field);
texram::Request trilinear_request(const Txn& item);

// The memory's counters over a sequence of accesses: the page model's statistics and a hash of
// every access's (bank, address) pairs in order. Golden feeds it its plans, the memory of the
// hls and rtl benches the accesses the unit makes.
class TexramAccessLog {
 public:
  // One access; returns its periods (1, or 2 on a page fault).
  int access(const std::array<std::optional<uint32_t>, 8>& addresses);
  // Every access of a sample: one per byte plane at address + plane; none if nothing is read.
  void sample(const std::array<std::optional<uint32_t>, 8>& addresses, int planes);
  Counters counters() const;

 private:
  texram::PageModel pages_;
  uint64_t hash_ = 0xCBF2'9CE4'8422'2325ull;  // FNV-1a offset basis
};

// The eight banks of the hls and rtl benches. An accepted access takes the page model's
// periods: ready is low for the extra period of a fault, and the response (every bank's byte;
// random bytes in the banks not read) is valid the cycle the access completes: the cycle after
// it was accepted on a page hit, two cycles after on a fault. Responses come in order. An
// access that reads no bank, or a cell beyond a bank, fails the run.
class TexramMemory {
 public:
  TexramMemory(std::shared_ptr<const texram::TexramTexture> texture, uint64_t seed);

  struct Inputs {
    bool req_ready = false;
    bool resp_valid = false;
    uint64_t resp_data = 0;  // bank b's byte at bits 8b + 7 .. 8b
  };
  // The memory's side of the ports for this cycle (the same values until sample()).
  Inputs drive();
  // The unit's request as seen before the edge; ends the cycle.
  void sample(bool req_valid, uint32_t enables, const std::array<uint32_t, 8>& addresses);

  static constexpr uint8_t kPoison = 0xA5;
  const std::string& error() const { return error_; }
  Counters counters() const { return log_.counters(); }

 private:
  struct Response {
    uint64_t due_cycle;
    uint64_t data;
  };
  std::shared_ptr<const texram::TexramTexture> texture_;
  std::mt19937_64 rng_;
  TexramAccessLog log_;
  uint64_t cycle_ = 0;
  uint64_t busy_until_ = 0;  // ready again from this cycle
  bool drawn_ = false;
  Inputs now_;
  std::deque<Response> responses_;
  std::string error_;
};

// Salt of the memory's generator, mixed with RunOptions::stalls.seed.
inline constexpr uint64_t kTexramMemorySeedSalt = 0x7E57'0000'7E1A'0001ull;

// The rtl engine for any Verilated model with the unit's ports (tests use mutants; the sweep
// uses models verilated with other widths: env.config.widths must be the model's).
template <class Model>
std::unique_ptr<Engine> make_trilinear_rtl_engine(const std::string& name, TrilinearEnv env);

}  // namespace tmu::tb

#include "blocks/trilinear_rtl.inl"
