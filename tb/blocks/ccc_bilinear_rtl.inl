// Port adapter of the low-cost CCC unit's Verilated models (included by ccc_bilinear_block.hpp):
// the stimulus ports, the quasi-static configuration and the texture memory.
#pragma once

#include <utility>

namespace tmu::tb {

template <class Model>
class CccBilinearRtlAdapter : public RtlAdapter<Model> {
 public:
  CccBilinearRtlAdapter(std::shared_ptr<const ccc::Texture> texture, bool lookahead,
                        uint64_t memory_seed)
      : texture_(texture), lookahead_(lookahead), memory_(std::move(texture), memory_seed) {}

  void drive(Model& m, const Txn* item) override {
    const bool write = item && item->f[kBilOp] == kBilOpClutWrite;
    const bool sample = item && item->f[kBilOp] == kBilOpSample;
    m.clut_valid_i = write;
    m.clut_addr_i = write ? static_cast<uint8_t>(item->f[kBilClutAddr]) : 0;
    m.clut_rgb_i = write ? static_cast<uint32_t>(item->f[kBilClutRgb]) : 0;
    m.req_valid_i = sample;
    m.req_u_i = sample ? static_cast<uint32_t>(item->f[kBilU]) : 0;  // raw SQ16.8 bits
    m.req_v_i = sample ? static_cast<uint32_t>(item->f[kBilV]) : 0;
  }
  bool accepts(const Model& m, const Txn& item) const override {
    return item.f[kBilOp] == kBilOpClutWrite ? m.clut_ready_o : m.req_ready_o;
  }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[0] = m.out_rgb_o;
    return t;
  }
  // The configuration is held from before reset; the memory answers every cycle.
  void env_drive(Model& m) override {
    m.cfg_width_i = static_cast<uint16_t>(texture_->width);
    m.cfg_height_i = static_cast<uint16_t>(texture_->height);
    m.cfg_lookahead_i = lookahead_;
    const TextureMemory::Inputs in = memory_.drive();
    m.mem_req_ready_i = in.req_ready;
    m.mem_resp_valid_i = in.resp_valid;
    m.mem_resp_block_i = in.resp_block;
  }
  void env_sample(const Model& m) override {
    memory_.sample(m.mem_req_valid_o, static_cast<uint32_t>(m.mem_req_addr_o));
  }
  std::string env_error() const override { return memory_.error(); }
  Counters counters(const Model& m) const override {
    return {
        {"hits", m.stat_hits_o}, {"misses", m.stat_misses_o}, {"prefetches", m.stat_prefetches_o}};
  }

 private:
  std::shared_ptr<const ccc::Texture> texture_;
  bool lookahead_;
  TextureMemory memory_;
};

template <class Model>
class CccBilinearRtlEngine : public Engine {
 public:
  CccBilinearRtlEngine(std::string name, std::shared_ptr<const ccc::Texture> texture,
                       bool lookahead)
      : name_(std::move(name)), texture_(std::move(texture)), lookahead_(lookahead) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    size_t expected = 0;
    for (const Txn& t : items) expected += t.f[kBilOp] == kBilOpSample;
    CccBilinearRtlAdapter<Model> adapter(texture_, lookahead_,
                                         options.stalls.seed ^ kTextureMemorySeedSalt);
    return run_rtl(adapter, items, expected, options);
  }

 private:
  std::string name_;
  std::shared_ptr<const ccc::Texture> texture_;
  bool lookahead_;
};

template <class Model>
std::unique_ptr<Engine> make_ccc_bilinear_rtl_engine(const std::string& name,
                                                     std::shared_ptr<const ccc::Texture> texture,
                                                     bool lookahead) {
  return std::make_unique<CccBilinearRtlEngine<Model>>(name, std::move(texture), lookahead);
}

}  // namespace tmu::tb
