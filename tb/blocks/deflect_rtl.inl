// Port adapter of the deflection unit's Verilated models (included by deflect_block.hpp): the
// request ports, the map memory and the monitor of the access codes.
#pragma once

#include <utility>

namespace tmu::tb {

template <class Model>
class DeflectRtlAdapter : public RtlAdapter<Model> {
 public:
  DeflectRtlAdapter(std::shared_ptr<const deflect::S2sMap> map, S2sMemoryTiming timing,
                    uint64_t memory_seed)
      : memory_(std::move(map), timing, memory_seed) {}

  void drive(Model& m, const Txn* item) override {
    m.in_valid_i = item != nullptr;
    m.in_normal_phi_i = item ? static_cast<uint16_t>(item->f[kDflNormalPhi]) : 0;
    m.in_normal_theta_i = item ? static_cast<uint8_t>(item->f[kDflNormalTheta]) : 0;
    m.in_bump_phi_i = item ? static_cast<uint16_t>(item->f[kDflBumpPhi]) : 0;
    m.in_bump_theta_i = item ? static_cast<uint8_t>(item->f[kDflBumpTheta]) : 0;
  }
  bool accepts(const Model& m, const Txn&) const override { return m.in_ready_o; }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kDflOutPhi] = m.out_phi_o;
    t.f[kDflOutTheta] = m.out_theta_o;
    t.f[kDflOutAccess] = m.out_access_o;
    return t;
  }
  void env_drive(Model& m) override {
    const S2sMemory::Inputs& in = memory_.drive();
    m.map_resp_valid_i = in.resp_valid;
    for (size_t w = 0; w < in.resp_words.size(); ++w) m.map_resp_data_i[w] = in.resp_words[w];
  }
  void env_sample(const Model& m) override {
    memory_.sample(m.map_req_valid_o, m.map_req_block_o);
    monitor_.sample(m.out_valid_o && m.out_ready_i, m.out_access_o);
  }
  std::string env_error() const override { return memory_.error(); }
  Counters counters(const Model&) const override {
    return deflect_bench_counters(monitor_, memory_);
  }

 private:
  S2sMemory memory_;
  MapAccessMonitor monitor_;
};

template <class Model>
class DeflectRtlEngine : public Engine {
 public:
  DeflectRtlEngine(std::string name, std::shared_ptr<const deflect::S2sMap> map,
                   S2sMemoryTiming timing)
      : name_(std::move(name)), map_(std::move(map)), timing_(timing) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    DeflectRtlAdapter<Model> adapter(map_, timing_, options.stalls.seed ^ kS2sMemorySeedSalt);
    return run_rtl(adapter, items, items.size(), options);
  }

 private:
  std::string name_;
  std::shared_ptr<const deflect::S2sMap> map_;
  S2sMemoryTiming timing_;
};

template <class Model>
std::unique_ptr<Engine> make_deflect_rtl_engine(const std::string& name,
                                                std::shared_ptr<const deflect::S2sMap> map,
                                                S2sMemoryTiming timing) {
  return std::make_unique<DeflectRtlEngine<Model>>(name, std::move(map), timing);
}

}  // namespace tmu::tb
