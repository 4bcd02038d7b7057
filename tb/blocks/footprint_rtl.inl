// Port adapter of the footprint unit's Verilated models (included by footprint_block.hpp): the
// stimulus ports, the quasi-static configuration (the trilinear unit's and the setup's) and
// the TEXRAM memory of the trilinear block.
#pragma once

#include <utility>

namespace tmu::tb {

template <class Model>
class FootprintRtlAdapter : public RtlAdapter<Model> {
 public:
  FootprintRtlAdapter(FootprintEnv env, uint64_t memory_seed)
      : env_(std::move(env)), memory_(env_.trilinear.texture, memory_seed) {}

  void drive(Model& m, const Txn* item) override {
    const bool write = item && item->f[kFpOp] == kFpOpClutWrite;
    const bool sample = item && item->f[kFpOp] == kFpOpSample;
    m.clut_valid_i = write;
    m.clut_addr_i = write ? static_cast<uint8_t>(item->f[kFpClutAddr]) : 0;
    m.clut_rgba_i = write ? static_cast<uint32_t>(item->f[kFpClutRgba]) : 0;
    m.req_valid_i = sample;
    // Raw SQ16.8 bits, as the items hold them.
    m.req_u_i = sample ? static_cast<uint32_t>(item->f[kFpU]) : 0;
    m.req_v_i = sample ? static_cast<uint32_t>(item->f[kFpV]) : 0;
    m.req_r1u_i = sample ? static_cast<uint32_t>(item->f[kFpR1u]) : 0;
    m.req_r1v_i = sample ? static_cast<uint32_t>(item->f[kFpR1v]) : 0;
    m.req_r2u_i = sample ? static_cast<uint32_t>(item->f[kFpR2u]) : 0;
    m.req_r2v_i = sample ? static_cast<uint32_t>(item->f[kFpR2v]) : 0;
    m.req_shade_i = sample ? static_cast<uint32_t>(item->f[kFpShade]) : 0;
  }
  bool accepts(const Model& m, const Txn& item) const override {
    return item.f[kFpOp] == kFpOpClutWrite ? m.clut_ready_o : m.req_ready_o;
  }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[0] = m.out_rgba_o;
    return t;
  }
  // The configuration is held from before reset; the memory answers every cycle.
  void env_drive(Model& m) override {
    const texram::SamplerConfig& c = env_.trilinear.config;
    const texram::Geometry& g = env_.trilinear.texture->geometry;
    m.cfg_log2_w_i = static_cast<uint8_t>(g.log2_width());
    m.cfg_log2_h_i = static_cast<uint8_t>(g.log2_height());
    m.cfg_kind_i = static_cast<uint8_t>(c.kind);
    m.cfg_single_channel_i = static_cast<uint8_t>(c.single_channel);
    m.cfg_filter_i = static_cast<uint8_t>(c.filter);
    m.cfg_border_u_i = static_cast<uint8_t>(c.border_u);
    m.cfg_border_v_i = static_cast<uint8_t>(c.border_v);
    m.cfg_border_rgba_i = c.border_rgba;
    m.cfg_combine_i = static_cast<uint8_t>(c.combine);
    m.cfg_constant_rgba_i = c.constant_rgba;
    m.cfg_log2_max_probes_i = static_cast<uint8_t>(env_.config.log2_max_probes);
    m.cfg_q_rule_i = static_cast<uint8_t>(env_.config.q_rule);
    const TexramMemory::Inputs in = memory_.drive();
    m.mem_req_ready_i = in.req_ready;
    m.mem_resp_valid_i = in.resp_valid;
    m.mem_resp_data_i = in.resp_data;
  }
  void env_sample(const Model& m) override {
    std::array<uint32_t, 8> addresses{};
    constexpr int kW = formats::kBankAddr.width();
    for (int b = 0; b < 8; ++b) {
      addresses[static_cast<size_t>(b)] = wide_bits(m.mem_req_addr_o, b * kW, kW);
    }
    memory_.sample(m.mem_req_valid_o, m.mem_req_en_o, addresses);
  }
  std::string env_error() const override { return memory_.error(); }
  Counters counters(const Model& m) const override {
    Counters c = memory_.counters();
    c.emplace_back("probes", m.stat_probes_o);
    return c;
  }

 private:
  FootprintEnv env_;
  TexramMemory memory_;
};

template <class Model>
class FootprintRtlEngine : public Engine {
 public:
  FootprintRtlEngine(std::string name, FootprintEnv env)
      : name_(std::move(name)), env_(std::move(env)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    size_t expected = 0;
    for (const Txn& t : items) expected += t.f[kFpOp] == kFpOpSample;
    FootprintRtlAdapter<Model> adapter(env_, options.stalls.seed ^ kTexramMemorySeedSalt);
    return run_rtl(adapter, items, expected, options);
  }

 private:
  std::string name_;
  FootprintEnv env_;
};

template <class Model>
std::unique_ptr<Engine> make_footprint_rtl_engine(const std::string& name, FootprintEnv env) {
  return std::make_unique<FootprintRtlEngine<Model>>(name, std::move(env));
}

}  // namespace tmu::tb
