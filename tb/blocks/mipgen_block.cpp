#include "blocks/mipgen_block.hpp"

#include <Vtmu_mipgen.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "formats/formats.hpp"
#include "harness/hls_runner.hpp"
#include "hls/texram/mipgen_sc.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;

namespace {

const Schema kInputs({{"texel", fmts::kChannel}, {"above", fmts::kChannel}});
const Schema kOutputs({{"level", fmts::kMipLevel},
                       {"x", fmts::kMipCoord},
                       {"y", fmts::kMipCoord},
                       {"value", fmts::kChannel},
                       {"bank", fmts::kBank},
                       {"addr", fmts::kBankAddr}});

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions, so the
// stimulus is the same on every standard library).
int uniform(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

class GoldenEngine : public Engine {
 public:
  explicit GoldenEngine(const texram::MipgenConfig& config) : config_(config) {}
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    const auto start = std::chrono::steady_clock::now();
    try {
      const std::vector<texram::CellWrite> writes =
          mipgen_golden_writes(config_, items, &r.output_items);
      r.outputs.reserve(writes.size());
      for (const texram::CellWrite& w : writes) r.outputs.push_back(mipgen_write_txn(w));
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    return r;
  }

 private:
  texram::MipgenConfig config_;
};

// The hls module with its signals, driven by the harness's ScDriver.
class HlsBench : public sc_core::sc_module, public ScAdapter {
 public:
  HlsBench(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
           const texram::MipgenConfig& config)
      : sc_module(name), dut_("dut"), config_(config) {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    dut_.cfg_log2_w_i(cfg_log2_w_);
    dut_.cfg_log2_h_i(cfg_log2_h_);
    dut_.cfg_interlaced_i(cfg_interlaced_);
    dut_.cfg_four_planes_i(cfg_four_planes_);
    dut_.cfg_plane_i(cfg_plane_);
    dut_.in_valid_i(in_valid_);
    dut_.in_ready_o(in_ready_);
    dut_.in_texel_i(in_texel_);
    dut_.in_above_i(in_above_);
    dut_.wr_valid_o(wr_valid_);
    dut_.wr_ready_i(wr_ready_);
    dut_.wr_level_o(wr_level_);
    dut_.wr_x_o(wr_x_);
    dut_.wr_y_o(wr_y_);
    dut_.wr_value_o(wr_value_);
    dut_.wr_bank_o(wr_bank_);
    dut_.wr_addr_o(wr_addr_);
  }
  void drive(const Txn* item) override {
    in_valid_.write(item != nullptr);
    in_texel_.write(item ? item->f[kMipTexel] : 0);
    in_above_.write(item ? item->f[kMipAbove] : 0);
  }
  bool accepts(const Txn&) const override { return in_ready_.read(); }
  void set_out_ready(bool ready) override { wr_ready_.write(ready); }
  bool out_valid() const override { return wr_valid_.read(); }
  Txn out() const override {
    Txn t;
    t.f[kMipLevel] = wr_level_.read();
    t.f[kMipX] = wr_x_.read();
    t.f[kMipY] = wr_y_.read();
    t.f[kMipValue] = wr_value_.read();
    t.f[kMipBank] = wr_bank_.read();
    t.f[kMipAddr] = wr_addr_.read();
    return t;
  }
  void env_drive() override {
    cfg_log2_w_.write(static_cast<unsigned>(config_.log2_w));
    cfg_log2_h_.write(static_cast<unsigned>(config_.log2_h));
    cfg_interlaced_.write(config_.interlaced);
    cfg_four_planes_.write(config_.planes == fmts::kPlanes);
    cfg_plane_.write(static_cast<unsigned>(config_.plane));
  }

 private:
  template <int W>
  using sig = sc_core::sc_signal<sc_dt::sc_uint<W>>;
  hls::MipgenSc dut_;
  texram::MipgenConfig config_;
  sig<fmts::kMipLog2.width()> cfg_log2_w_{"cfg_log2_w"}, cfg_log2_h_{"cfg_log2_h"};
  sc_core::sc_signal<bool> cfg_interlaced_{"cfg_interlaced"}, cfg_four_planes_{"cfg_four_planes"};
  sig<fmts::kBytePlane.width()> cfg_plane_{"cfg_plane"};
  sc_core::sc_signal<bool> in_valid_{"in_valid"}, in_ready_{"in_ready"};
  sig<fmts::kChannel.width()> in_texel_{"in_texel"}, in_above_{"in_above"};
  sc_core::sc_signal<bool> wr_valid_{"wr_valid"}, wr_ready_{"wr_ready"};
  sig<fmts::kMipLevel.width()> wr_level_{"wr_level"};
  sig<fmts::kMipCoord.width()> wr_x_{"wr_x"}, wr_y_{"wr_y"};
  sig<fmts::kChannel.width()> wr_value_{"wr_value"};
  sig<fmts::kBank.width()> wr_bank_{"wr_bank"};
  sig<fmts::kBankAddr.width()> wr_addr_{"wr_addr"};
};

class HlsEngine : public Engine {
 public:
  explicit HlsEngine(const texram::MipgenConfig& config) : config_(config) {}
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<HlsBench>(
        [this](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<HlsBench>("bench", clk, rst_n, config_);
        },
        items, mipgen_golden_writes(config_, items).size(), options);
  }

 private:
  texram::MipgenConfig config_;
};

texram::Level8 filled(uint32_t w, uint32_t h, uint8_t v) {
  texram::Level8 l(w, h);
  std::fill(l.texels.begin(), l.texels.end(), v);
  return l;
}

const char* const kReplicas = "replica writes (level < 2 wide/high)";
const char* const kField2 = "interlaced field-2 item (with above)";
const char* const kTie = "rounding tie (box sum = 2 mod 4)";
const char* const kSum0 = "box sum 0";
const char* const kSum1020 = "box sum 1020 (all 255)";
const char* const kFrameStart = "first texel of a later frame";
const char* const kFrameEnd = "last texel of a frame (top level)";

std::string level_case(int level) { return fmt::format("writes to level {}", level); }

}  // namespace

// ---- Items, writes and engines -------------------------------------------------------------

texram::MipgenConfig random_mipgen_config(uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x3109'6E17'0000'0001ull);
  const int max_log2 = fmts::kMaxMipLog2;
  texram::MipgenConfig c;
  const uint64_t r = rng() % 16;
  if (r < 2) {  // one texel wide
    c.log2_w = 0;
    c.log2_h = uniform(rng, 0, 6);
  } else if (r < 4) {  // one line
    c.log2_w = uniform(rng, 0, 6);
    c.log2_h = 0;
  } else if (r == 4) {  // long lines: 1024 x 1..4
    c.log2_w = max_log2;
    c.log2_h = uniform(rng, 0, 2);
  } else if (r == 5) {  // tall columns: 1..4 x 1024
    c.log2_w = uniform(rng, 0, 2);
    c.log2_h = max_log2;
  } else if (r == 6) {  // larger frames, up to 128 x 128
    c.log2_w = uniform(rng, 5, 7);
    c.log2_h = uniform(rng, 5, 7);
  } else {  // small: 1..32 per side
    c.log2_w = uniform(rng, 0, 5);
    c.log2_h = uniform(rng, 0, 5);
  }
  c.interlaced = (rng() & 1) != 0;
  c.planes = (rng() & 1) ? fmts::kPlanes : 1;
  c.plane = uniform(rng, 0, c.planes - 1);
  return c;
}

std::vector<Txn> mipgen_frame_items(const texram::Level8& level0, bool interlaced) {
  std::vector<Txn> items;
  items.reserve(level0.texels.size());
  for (const texram::MipgenInput& in : texram::mipgen_source(level0, interlaced)) {
    Txn t;
    t.f[kMipTexel] = in.texel;
    t.f[kMipAbove] = in.above;
    items.push_back(t);
  }
  return items;
}

texram::Level8 mipgen_tie_frame(int log2_w, int log2_h) {
  // Top down from 128: a texel u of level l + 1 has the children (u-1, u-1, u-1, u+1) (sum
  // 4u - 2) when level l is at least 2 x 2, (u-1, u) (sum 2(2u - 1)) when it is one texel wide
  // or high; either way (sum + 2) >> 2 = u and the sum is 2 mod 4. Which child is the odd one
  // out moves with the position. Values stay within 128 +- 10.
  const texram::Geometry g(log2_w, log2_h);
  texram::Level8 above(1, 1);
  above.at(0, 0) = 128;
  for (int l = g.levels() - 2; l >= 0; --l) {
    texram::Level8 cur(g.texel_width(l), g.texel_height(l));
    const bool wide = cur.width >= 2, high = cur.height >= 2;
    for (uint32_t y = 0; y < cur.height; ++y) {
      for (uint32_t x = 0; x < cur.width; ++x) {
        const uint32_t px = wide ? x / 2 : 0, py = high ? y / 2 : 0;
        const int u = above.at(px, py);
        int v;
        if (wide && high) {
          const uint32_t odd_one = (px + py) & 3u;
          v = ((x & 1u) + 2 * (y & 1u)) == odd_one ? u + 1 : u - 1;
        } else {
          const uint32_t bit = wide ? (x & 1u) : (y & 1u);
          v = bit == ((px + py) & 1u) ? u : u - 1;
        }
        cur.at(x, y) = static_cast<uint8_t>(v);
      }
    }
    above = std::move(cur);
  }
  return above;
}

Txn mipgen_write_txn(const texram::CellWrite& w) {
  Txn t;
  t.f[kMipLevel] = static_cast<uint64_t>(w.level);
  t.f[kMipX] = w.x;
  t.f[kMipY] = w.y;
  t.f[kMipValue] = w.value;
  t.f[kMipBank] = w.cell.bank;
  t.f[kMipAddr] = w.cell.address;
  return t;
}

texram::CellWrite mipgen_txn_write(const Txn& t) {
  texram::CellWrite w;
  w.level = static_cast<int>(t.f[kMipLevel]);
  w.x = static_cast<uint32_t>(t.f[kMipX]);
  w.y = static_cast<uint32_t>(t.f[kMipY]);
  w.value = static_cast<uint8_t>(t.f[kMipValue]);
  w.cell = {static_cast<unsigned>(t.f[kMipBank]), static_cast<uint32_t>(t.f[kMipAddr])};
  return w;
}

std::vector<texram::CellWrite> mipgen_golden_writes(const texram::MipgenConfig& config,
                                                    const std::vector<Txn>& items,
                                                    std::vector<size_t>* item_of_write) {
  texram::MipgenStream stream(config);
  std::vector<texram::CellWrite> writes;
  writes.reserve(items.size() * 3 / 2 + 64);
  for (size_t i = 0; i < items.size(); ++i) {
    const Txn& t = items[i];
    stream.step({static_cast<uint8_t>(t.f[kMipTexel]), static_cast<uint8_t>(t.f[kMipAbove])},
                writes);
    if (item_of_write) item_of_write->resize(writes.size(), i);
  }
  return writes;
}

std::unique_ptr<Engine> make_mipgen_engine(const std::string& level,
                                           const texram::MipgenConfig& config) {
  if (level == "golden") return std::make_unique<GoldenEngine>(config);
  if (level == "hls") return std::make_unique<HlsEngine>(config);
  if (level == "rtl") return make_mipgen_rtl_engine<Vtmu_mipgen>("rtl", config);
  throw std::invalid_argument("mipgen: no engine '" + level + "' (golden, hls, rtl)");
}

// ---- The block ---------------------------------------------------------------------------

struct MipgenBlock::CoverState {
  explicit CoverState(const texram::MipgenConfig& c) : stream(c) {}
  texram::MipgenStream stream;
  size_t next = 0;  // the item the stream expects next
  std::vector<texram::CellWrite> writes;
};

MipgenBlock::MipgenBlock(const BlockOptions& options)
    : options_(options), config_(random_mipgen_config(options.seed)) {
  auto check = [](int v, int lo, int hi, const char* what) {
    if (v < lo || v > hi) {
      throw std::invalid_argument(fmt::format("mipgen: {} {} is outside {}..{}", what, v, lo, hi));
    }
    return v;
  };
  if (options.mip_log2_w >= 0)
    config_.log2_w = check(options.mip_log2_w, 0, fmts::kMaxMipLog2, "log2 width");
  if (options.mip_log2_h >= 0)
    config_.log2_h = check(options.mip_log2_h, 0, fmts::kMaxMipLog2, "log2 height");
  if (options.mip_interlaced >= 0)
    config_.interlaced = check(options.mip_interlaced, 0, 1, "interlaced") != 0;
}

MipgenBlock::~MipgenBlock() = default;

const Schema& MipgenBlock::inputs() const { return kInputs; }
const Schema& MipgenBlock::outputs() const { return kOutputs; }

std::string MipgenBlock::repro_options() const {
  std::string out;
  if (options_.mip_log2_w >= 0) out += fmt::format(" --mip-log2-w {}", options_.mip_log2_w);
  if (options_.mip_log2_h >= 0) out += fmt::format(" --mip-log2-h {}", options_.mip_log2_h);
  if (options_.mip_interlaced >= 0)
    out += fmt::format(" --mip-interlaced {}", options_.mip_interlaced);
  return out.empty() ? out : out.substr(1);
}

std::vector<Txn> MipgenBlock::directed_items() const {
  const uint32_t w = 1u << config_.log2_w, h = 1u << config_.log2_h;
  texram::Level8 alternating(w, h);
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) alternating.at(x, y) = ((x + y) & 1u) ? 255 : 0;
  }
  std::vector<Txn> items;
  for (const texram::Level8& frame : {filled(w, h, 0), filled(w, h, 255), alternating,
                                      mipgen_tie_frame(config_.log2_w, config_.log2_h)}) {
    for (const Txn& t : mipgen_frame_items(frame, config_.interlaced)) items.push_back(t);
  }
  return items;
}

std::vector<Txn> MipgenBlock::random_items(std::mt19937_64& rng, size_t count) const {
  const uint32_t w = 1u << config_.log2_w, h = 1u << config_.log2_h;
  std::vector<Txn> items;
  while (items.size() < count) {
    texram::Level8 frame(w, h);
    for (uint8_t& t : frame.texels) t = static_cast<uint8_t>(rng());
    for (const Txn& t : mipgen_frame_items(frame, config_.interlaced)) items.push_back(t);
  }
  return items;
}

std::unique_ptr<Engine> MipgenBlock::engine(const std::string& level) const {
  return make_mipgen_engine(level, config_);
}

std::vector<std::string> MipgenBlock::coverage_cases() const {
  const texram::MipgenStream s(config_);
  std::vector<std::string> cases;
  for (int l = 0; l < s.geometry().levels(); ++l) cases.push_back(level_case(l));
  cases.push_back(kReplicas);
  if (s.interlaced()) cases.push_back(kField2);
  if (s.geometry().levels() > 1) {
    cases.push_back(kTie);
    cases.push_back(kSum0);
    cases.push_back(kSum1020);
  }
  cases.push_back(kFrameStart);
  cases.push_back(kFrameEnd);
  return cases;
}

void MipgenBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                        Coverage& cov) const {
  // The harness calls this for items 0, 1, 2, ... in order; any other order replays.
  if (!cover_ || index < cover_->next) cover_ = std::make_unique<CoverState>(config_);
  texram::MipgenStream& s = cover_->stream;
  auto step = [&](size_t i) {
    cover_->writes.clear();
    s.step(
        {static_cast<uint8_t>(items[i].f[kMipTexel]), static_cast<uint8_t>(items[i].f[kMipAbove])},
        cover_->writes);
    cover_->next = i + 1;
  };
  while (cover_->next < index) step(cover_->next);
  const bool later_frame = index > 0 && s.frame_start();
  const bool field2 = s.needs_above();
  step(index);
  const texram::Geometry& g = s.geometry();
  bool top = false;  // the 1 x 1 level is written by a frame's last texel only
  for (const texram::CellWrite& w : cover_->writes) {
    ++cov[level_case(w.level)];
    if (g.grid_width(w.level) < 2 || g.grid_height(w.level) < 2) ++cov[kReplicas];
    top = top || w.level == g.levels() - 1;
  }
  if (top) ++cov[kFrameEnd];
  if (field2) ++cov[kField2];
  if (later_frame) ++cov[kFrameStart];
  for (const uint32_t sum : s.last_box_sums()) {
    if (sum % 4 == 2) ++cov[kTie];
    if (sum == 0) ++cov[kSum0];
    if (sum == 1020) ++cov[kSum1020];
  }
}

std::vector<Port> MipgenBlock::ports() const {
  return {{"clk_i"},
          {"rst_ni"},
          {"cfg_log2_w_i", fmts::kMipLog2.width()},
          {"cfg_log2_h_i", fmts::kMipLog2.width()},
          {"cfg_interlaced_i"},
          {"cfg_four_planes_i"},
          {"cfg_plane_i", fmts::kBytePlane.width()},
          {"in_valid_i"},
          {"in_ready_o"},
          {"in_texel_i", fmts::kChannel.width()},
          {"in_above_i", fmts::kChannel.width()},
          {"wr_valid_o"},
          {"wr_ready_i"},
          {"wr_level_o", fmts::kMipLevel.width()},
          {"wr_x_o", fmts::kMipCoord.width()},
          {"wr_y_o", fmts::kMipCoord.width()},
          {"wr_value_o", fmts::kChannel.width()},
          {"wr_bank_o", fmts::kBank.width()},
          {"wr_addr_o", fmts::kBankAddr.width()}};
}

}  // namespace tmu::tb
