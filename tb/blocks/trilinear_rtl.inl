// Port adapter of the TEXRAM trilinear unit's Verilated models (included by
// trilinear_block.hpp): the stimulus ports, the quasi-static configuration and the memory.
#pragma once

#include <utility>

namespace tmu::tb {

// Bits lo .. lo + width - 1 (width <= 32) of a Verilated wide port (32-bit words).
template <class Wide>
uint32_t wide_bits(const Wide& w, int lo, int width) {
  const auto word = static_cast<size_t>(lo / 32);
  uint64_t v = w[word];
  if (lo % 32 + width > 32) v |= uint64_t{w[word + 1]} << 32;
  return static_cast<uint32_t>((v >> (lo % 32)) & ((uint64_t{1} << width) - 1));
}

template <class Model>
class TrilinearRtlAdapter : public RtlAdapter<Model> {
 public:
  TrilinearRtlAdapter(TrilinearEnv env, uint64_t memory_seed)
      : env_(std::move(env)), memory_(env_.texture, memory_seed) {}

  void drive(Model& m, const Txn* item) override {
    const bool write = item && item->f[kTriOp] == kTriOpClutWrite;
    const bool sample = item && item->f[kTriOp] == kTriOpSample;
    m.clut_valid_i = write;
    m.clut_addr_i = write ? static_cast<uint8_t>(item->f[kTriClutAddr]) : 0;
    m.clut_rgba_i = write ? static_cast<uint32_t>(item->f[kTriClutRgba]) : 0;
    m.req_valid_i = sample;
    m.req_u_i = sample ? static_cast<uint32_t>(item->f[kTriU]) : 0;  // raw SQ16.8 bits
    m.req_v_i = sample ? static_cast<uint32_t>(item->f[kTriV]) : 0;
    m.req_lambda_i = sample ? static_cast<uint16_t>(item->f[kTriLambda]) : 0;  // raw SQ6.8
    m.req_shade_i = sample ? static_cast<uint32_t>(item->f[kTriShade]) : 0;
  }
  bool accepts(const Model& m, const Txn& item) const override {
    return item.f[kTriOp] == kTriOpClutWrite ? m.clut_ready_o : m.req_ready_o;
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
    const texram::SamplerConfig& c = env_.config;
    const texram::Geometry& g = env_.texture->geometry;
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
  Counters counters(const Model&) const override { return memory_.counters(); }

 private:
  TrilinearEnv env_;
  TexramMemory memory_;
};

template <class Model>
class TrilinearRtlEngine : public Engine {
 public:
  TrilinearRtlEngine(std::string name, TrilinearEnv env)
      : name_(std::move(name)), env_(std::move(env)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    size_t expected = 0;
    for (const Txn& t : items) expected += t.f[kTriOp] == kTriOpSample;
    TrilinearRtlAdapter<Model> adapter(env_, options.stalls.seed ^ kTexramMemorySeedSalt);
    return run_rtl(adapter, items, expected, options);
  }

 private:
  std::string name_;
  TrilinearEnv env_;
};

template <class Model>
std::unique_ptr<Engine> make_trilinear_rtl_engine(const std::string& name, TrilinearEnv env) {
  return std::make_unique<TrilinearRtlEngine<Model>>(name, std::move(env));
}

}  // namespace tmu::tb
