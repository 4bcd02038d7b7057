#include "render/volume_engine_block.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "blocks/volume/volume_block.hpp"
#include "harness/scoreboard.hpp"

namespace tmu::render {
namespace {

using tb::Txn;

using VolumePorts = tb::desc::volume;

// The pages open after a run that started with `open` and made `requests` (mem_req, in order):
// each bank's last read. Read from the engine's own requests, not from a model of them.
texram::OpenPages pages_after(texram::OpenPages open, const std::vector<Txn>& requests) {
  for (const Txn& r : requests) {
    for (size_t b = 0; b < open.size(); ++b) {
      if (r.f[VolumePorts::mem_req_en + b] == 0) continue;
      open[b] = static_cast<uint32_t>(r.f[VolumePorts::mem_req_addr + b]) >> texram::kPageBits;
    }
  }
  return open;
}

uint64_t run_counter(const tb::RunResult& r, const std::string& name, const std::string& engine) {
  const auto v = tb::counter_value(r.counters, name);
  if (!v) throw std::runtime_error(fmt::format("volume unit ({}): no counter {}", engine, name));
  return *v;
}

class BlockVolumeEngine final : public VolumeUnitEngine {
 public:
  BlockVolumeEngine(Level level, const volume::VoxelGrid& grid, const volume::Config& config,
                    const VolumeEngineOptions& options)
      : level_(level), options_(options) {
    setup_.config = config;
    setup_.size = {grid.nx, grid.ny, grid.nz};
    auto store = std::make_shared<tb::VolumeStore>();
    store->hold(setup_, grid);
    block_ = std::make_unique<tb::VolumeBlock>(tb::BlockOptions{}, store);
    if (options.check) check_.emplace().against = std::string(name(*options.check));
  }

  std::vector<VolumeSample> cast(const std::vector<VolumeCommand>& commands) override {
    std::vector<VolumeSample> out;
    for (size_t i = 0; i < commands.size();) {
      std::vector<Txn> items = {tb::volume_cfg_item(setup_)};
      uint64_t n = 0;
      size_t j = i;
      for (; j < commands.size(); ++j) {
        if (j > i && n + commands[j].ray.count > kVolumePieceResamples) break;
        items.push_back(tb::volume_ray_item(commands[j].ray));
        n += commands[j].ray.count;
      }
      run_piece(items, n, out);
      i = j;
    }
    return out;
  }

  VolumeCounters counters() const override { return counters_; }
  bool has_memory() const override { return true; }
  uint64_t cycles() const override { return cycles_; }
  uint64_t pieces() const override { return pieces_; }
  std::optional<VolumePieceCheck> piece_check() const override { return check_; }

 private:
  std::string label() const {
    return fmt::format("{}{}{}", name(level_), options_.name.empty() ? "" : ", ", options_.name);
  }

  tb::RunResult run_at(Level level, const texram::OpenPages& open, const std::vector<Txn>& items) {
    block_->set_open_pages(open);
    tb::RunResult r = block_->engine(engine_name(level))->run(items, {});
    if (!r.error.empty()) {
      throw std::runtime_error(fmt::format("volume unit ({}, {}) failed in piece {}: {}",
                                           name(level), options_.name, pieces_, r.error));
    }
    return r;
  }

  void run_piece(const std::vector<Txn>& items, uint64_t resamples,
                 std::vector<VolumeSample>& out) {
    tb::RunResult r = run_at(level_, open_, items);
    if (options_.inject_fault >= 0 && static_cast<uint64_t>(options_.inject_fault) >= outputs_ &&
        static_cast<uint64_t>(options_.inject_fault) < outputs_ + r.outputs.size()) {
      // A deliberate wrong bit: the value's LSB of one output.
      r.outputs[static_cast<size_t>(options_.inject_fault) - outputs_].f[VolumePorts::out_value] ^=
          1;
    }
    if (r.outputs.size() != resamples) {
      throw std::runtime_error(
          fmt::format("volume unit ({}): piece {} gave {} outputs for {} "
                      "resamples",
                      label(), pieces_, r.outputs.size(), resamples));
    }
    if (check_) compare_piece(items, r);
    open_ = pages_after(open_, r.requests.at(0));
    const std::string e = label();
    counters_.rays += run_counter(r, "rays", e);
    counters_.resamples += run_counter(r, "resamples", e);
    counters_.accesses += run_counter(r, "accesses", e);
    counters_.bank_reads += run_counter(r, "bank_reads", e);
    counters_.page_faults += run_counter(r, "page_faults", e);
    counters_.slow_accesses += run_counter(r, "slow_accesses", e);
    cycles_ += r.cycles;
    ++pieces_;
    outputs_ += r.outputs.size();
    for (const Txn& t : r.outputs) {
      const volume::Resample s = tb::volume_resample_of(t);
      out.push_back(
          {static_cast<double>(s.value), glm::dvec3(s.gradient[0], s.gradient[1], s.gradient[2]) /
                                             static_cast<double>(1 << volume::kGradFrac)});
    }
  }

  // The piece at the reference level, from the reference's own open pages.
  void compare_piece(const std::vector<Txn>& items, const tb::RunResult& got) {
    const tb::RunResult ref = run_at(*options_.check, check_open_, items);
    check_open_ = pages_after(check_open_, ref.requests.at(0));
    const tb::Comparison c = tb::compare(block_->outputs(), ref, got, block_->request_schemas());
    ++check_->pieces;
    check_->outputs += ref.outputs.size();
    check_->requests += ref.requests.at(0).size();
    if (c.match()) return;
    ++check_->differing_pieces;
    if (check_->first.size() >= 5) return;
    std::vector<std::string> parts;
    if (!c.error.empty()) parts.push_back("run failed: " + c.error);
    if (c.first) {
      std::vector<std::string> fields;
      for (int f : c.first->fields)
        fields.push_back(block_->outputs().field(static_cast<size_t>(f)).name);
      parts.push_back(fmt::format(
          "{} of {} outputs differ, first output {} of the piece, {} of the engine ({})",
          c.mismatches, c.compared, c.first->output_index, outputs_ + c.first->output_index,
          c.first->got ? fmt::format("{}", fmt::join(fields, ", ")) : "missing"));
    }
    for (const tb::Comparison::RequestMismatch& m : c.requests) {
      parts.push_back(fmt::format("{} memory requests differ, first request {}", m.differing,
                                  m.first.output_index));
    }
    for (const std::string& d : c.counter_diffs) parts.push_back("counter " + d);
    check_->first.push_back(
        fmt::format("{} piece {}: {}", label(), pieces_, fmt::join(parts, "; ")));
  }

  Level level_;
  VolumeEngineOptions options_;
  tb::VolumeSetup setup_;
  std::unique_ptr<tb::VolumeBlock> block_;
  texram::OpenPages open_{}, check_open_{};
  VolumeCounters counters_;
  uint64_t cycles_ = 0, pieces_ = 0, outputs_ = 0;
  std::optional<VolumePieceCheck> check_;
};

}  // namespace

std::unique_ptr<VolumeUnitEngine> make_block_volume_engine(Level level,
                                                           const volume::VoxelGrid& grid,
                                                           const volume::Config& config,
                                                           const VolumeEngineOptions& options) {
  if (level != Level::kHls && level != Level::kRtl) {
    throw std::logic_error("make_block_volume_engine: hls or rtl");
  }
  return std::make_unique<BlockVolumeEngine>(level, grid, config, options);
}

}  // namespace tmu::render
