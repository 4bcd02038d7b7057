#include "blocks/footprint_hls.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "fixed/fixed.hpp"
#include "formats/formats.hpp"
#include "harness/hls_runner.hpp"
#include "hls/footprint/footprint_sc.hpp"

namespace tmu::tb {
namespace {

namespace fmts = tmu::formats;

// A field's raw port bits as the signed value of its format.
int32_t signed_field(uint64_t field, const fx::Format& f) {
  const uint64_t bits = field & ((uint64_t{1} << f.width()) - 1);
  return static_cast<int32_t>(fx::fit(static_cast<int64_t>(bits), f, fx::Overflow::kWrap));
}

size_t count_samples(const std::vector<Txn>& items) {
  size_t n = 0;
  for (const Txn& t : items) n += t.f[kFpOp] == kFpOpSample;
  return n;
}

// The hls module with its signals and the memory, driven by the harness's ScDriver.
class Bench : public sc_core::sc_module, public ScAdapter {
 public:
  using Dut = hls::FootprintSc;

  Bench(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
        FootprintEnv env, uint64_t memory_seed)
      : sc_module(name),
        dut_("dut", env.config.widths, env.trilinear.config.widths),
        env_(std::move(env)),
        memory_(env_.trilinear.texture, memory_seed) {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    dut_.cfg_log2_w_i(cfg_log2_w_);
    dut_.cfg_log2_h_i(cfg_log2_h_);
    dut_.cfg_kind_i(cfg_kind_);
    dut_.cfg_single_channel_i(cfg_single_channel_);
    dut_.cfg_filter_i(cfg_filter_);
    dut_.cfg_border_u_i(cfg_border_u_);
    dut_.cfg_border_v_i(cfg_border_v_);
    dut_.cfg_border_rgba_i(cfg_border_rgba_);
    dut_.cfg_combine_i(cfg_combine_);
    dut_.cfg_constant_rgba_i(cfg_constant_rgba_);
    dut_.cfg_log2_max_probes_i(cfg_log2_max_probes_);
    dut_.cfg_q_rule_i(cfg_q_rule_);
    dut_.clut_valid_i(clut_valid_);
    dut_.clut_ready_o(clut_ready_);
    dut_.clut_addr_i(clut_addr_);
    dut_.clut_rgba_i(clut_rgba_);
    dut_.req_valid_i(req_valid_);
    dut_.req_ready_o(req_ready_);
    dut_.req_u_i(req_u_);
    dut_.req_v_i(req_v_);
    dut_.req_r1u_i(req_r1u_);
    dut_.req_r1v_i(req_r1v_);
    dut_.req_r2u_i(req_r2u_);
    dut_.req_r2v_i(req_r2v_);
    dut_.req_shade_i(req_shade_);
    dut_.mem_req_valid_o(mem_req_valid_);
    dut_.mem_req_ready_i(mem_req_ready_);
    dut_.mem_req_en_o(mem_req_en_);
    dut_.mem_req_addr_o(mem_req_addr_);
    dut_.mem_resp_valid_i(mem_resp_valid_);
    dut_.mem_resp_data_i(mem_resp_data_);
    dut_.out_valid_o(out_valid_);
    dut_.out_ready_i(out_ready_);
    dut_.out_rgba_o(out_rgba_);
    dut_.stat_probes_o(stat_probes_);
  }

  void drive(const Txn* item) override {
    const bool write = item && item->f[kFpOp] == kFpOpClutWrite;
    const bool sample = item && item->f[kFpOp] == kFpOpSample;
    clut_valid_.write(write);
    clut_addr_.write(write ? item->f[kFpClutAddr] : 0);
    clut_rgba_.write(write ? item->f[kFpClutRgba] : 0);
    req_valid_.write(sample);
    const auto field = [&](FootprintField f, const fx::Format& format) {
      return sample ? signed_field(item->f[f], format) : 0;
    };
    req_u_.write(field(kFpU, fmts::kTexCoord));
    req_v_.write(field(kFpV, fmts::kTexCoord));
    req_r1u_.write(field(kFpR1u, fmts::kTexDeriv));
    req_r1v_.write(field(kFpR1v, fmts::kTexDeriv));
    req_r2u_.write(field(kFpR2u, fmts::kTexDeriv));
    req_r2v_.write(field(kFpR2v, fmts::kTexDeriv));
    req_shade_.write(sample ? item->f[kFpShade] : 0);
  }
  bool accepts(const Txn& item) const override {
    return item.f[kFpOp] == kFpOpClutWrite ? clut_ready_.read() : req_ready_.read();
  }
  void set_out_ready(bool ready) override { out_ready_.write(ready); }
  bool out_valid() const override { return out_valid_.read(); }
  Txn out() const override {
    Txn t;
    t.f[0] = out_rgba_.read();
    return t;
  }
  void env_drive() override {
    const texram::SamplerConfig& c = env_.trilinear.config;
    const texram::Geometry& g = env_.trilinear.texture->geometry;
    cfg_log2_w_.write(static_cast<unsigned>(g.log2_width()));
    cfg_log2_h_.write(static_cast<unsigned>(g.log2_height()));
    cfg_kind_.write(static_cast<unsigned>(c.kind));
    cfg_single_channel_.write(static_cast<unsigned>(c.single_channel));
    cfg_filter_.write(static_cast<unsigned>(c.filter));
    cfg_border_u_.write(static_cast<unsigned>(c.border_u));
    cfg_border_v_.write(static_cast<unsigned>(c.border_v));
    cfg_border_rgba_.write(c.border_rgba);
    cfg_combine_.write(static_cast<unsigned>(c.combine));
    cfg_constant_rgba_.write(c.constant_rgba);
    cfg_log2_max_probes_.write(static_cast<unsigned>(env_.config.log2_max_probes));
    cfg_q_rule_.write(static_cast<unsigned>(env_.config.q_rule));
    const TexramMemory::Inputs in = memory_.drive();
    mem_req_ready_.write(in.req_ready);
    mem_resp_valid_.write(in.resp_valid);
    mem_resp_data_.write(in.resp_data);
  }
  void env_sample() override {
    constexpr int kW = Dut::kAddrWidth;
    std::array<uint32_t, 8> addresses{};
    const auto bus = mem_req_addr_.read();
    for (int b = 0; b < 8; ++b) {
      addresses[static_cast<size_t>(b)] =
          static_cast<uint32_t>(bus.range((b + 1) * kW - 1, b * kW).to_uint());
    }
    memory_.sample(mem_req_valid_.read(), static_cast<uint32_t>(mem_req_en_.read()), addresses);
  }
  std::string env_error() const override { return memory_.error(); }
  Counters counters() const override {
    Counters c = memory_.counters();
    c.emplace_back("probes", stat_probes_.read().to_uint64());
    return c;
  }

 private:
  template <int W>
  using sig = sc_core::sc_signal<sc_dt::sc_uint<W>>;
  template <int W>
  using ssig = sc_core::sc_signal<sc_dt::sc_int<W>>;

  Dut dut_;
  FootprintEnv env_;
  TexramMemory memory_;
  sig<fmts::kMipLog2.width()> cfg_log2_w_{"cfg_log2_w"}, cfg_log2_h_{"cfg_log2_h"};
  sig<fmts::kTexKind.width()> cfg_kind_{"cfg_kind"};
  sig<fmts::kBytePlane.width()> cfg_single_channel_{"cfg_single_channel"};
  sig<fmts::kTexFilter.width()> cfg_filter_{"cfg_filter"};
  sig<fmts::kTexBorder.width()> cfg_border_u_{"cfg_border_u"}, cfg_border_v_{"cfg_border_v"};
  sig<fmts::kRgba8888.width()> cfg_border_rgba_{"cfg_border_rgba"};
  sig<fmts::kTexCombine.width()> cfg_combine_{"cfg_combine"};
  sig<fmts::kRgba8888.width()> cfg_constant_rgba_{"cfg_constant_rgba"};
  sig<fmts::kProbeLog2.width()> cfg_log2_max_probes_{"cfg_log2_max_probes"};
  sig<fmts::kQRule.width()> cfg_q_rule_{"cfg_q_rule"};
  sc_core::sc_signal<bool> clut_valid_{"clut_valid"}, clut_ready_{"clut_ready"};
  sig<fmts::kClutIndex.width()> clut_addr_{"clut_addr"};
  sig<fmts::kRgba8888.width()> clut_rgba_{"clut_rgba"};
  sc_core::sc_signal<bool> req_valid_{"req_valid"}, req_ready_{"req_ready"};
  ssig<fmts::kTexCoord.width()> req_u_{"req_u"}, req_v_{"req_v"};
  ssig<fmts::kTexDeriv.width()> req_r1u_{"req_r1u"}, req_r1v_{"req_r1v"};
  ssig<fmts::kTexDeriv.width()> req_r2u_{"req_r2u"}, req_r2v_{"req_r2v"};
  sig<fmts::kRgba8888.width()> req_shade_{"req_shade"};
  sc_core::sc_signal<bool> mem_req_valid_{"mem_req_valid"}, mem_req_ready_{"mem_req_ready"};
  sig<Dut::kBanks> mem_req_en_{"mem_req_en"};
  sc_core::sc_signal<sc_dt::sc_biguint<Dut::kAddrBusWidth>> mem_req_addr_{"mem_req_addr"};
  sc_core::sc_signal<bool> mem_resp_valid_{"mem_resp_valid"};
  sig<Dut::kDataWidth> mem_resp_data_{"mem_resp_data"};
  sc_core::sc_signal<bool> out_valid_{"out_valid"}, out_ready_{"out_ready"};
  sig<fmts::kRgba8888.width()> out_rgba_{"out_rgba"};
  sig<Dut::kStatWidth> stat_probes_{"stat_probes"};
};

class HlsEngine : public Engine {
 public:
  explicit HlsEngine(FootprintEnv env) : env_(std::move(env)) {}
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<Bench>(
        [&](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<Bench>("bench", clk, rst_n, env_,
                                         options.stalls.seed ^ kTexramMemorySeedSalt);
        },
        items, count_samples(items), options);
  }

 private:
  FootprintEnv env_;
};

}  // namespace

std::unique_ptr<Engine> make_footprint_hls_engine(const FootprintEnv& env) {
  return std::make_unique<HlsEngine>(env);
}

}  // namespace tmu::tb
