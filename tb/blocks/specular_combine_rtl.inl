// Port adapter of the specular combine's Verilated models (included by
// specular_combine_block.hpp).
#pragma once

namespace tmu::tb {

template <class Model>
class SpecularCombineRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override {
    m.in_valid_i = item != nullptr;
    m.in_diffuse_i = item ? static_cast<uint32_t>(item->f[kSpcDiffuse]) : 0;
    m.in_specular_i = item ? static_cast<uint32_t>(item->f[kSpcSpecular]) : 0;
    m.in_reflectance_i = item ? static_cast<uint32_t>(item->f[kSpcReflectance]) : 0;
  }
  bool accepts(const Model& m, const Txn&) const override { return m.in_ready_o; }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kSpcColour] = m.out_colour_o;
    return t;
  }
};

template <class Model>
class SpecularCombineRtlEngine : public Engine {
 public:
  explicit SpecularCombineRtlEngine(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    SpecularCombineRtlAdapter<Model> adapter;
    return run_rtl(adapter, items, items.size(), options);
  }

 private:
  std::string name_;
};

template <class Model>
std::unique_ptr<Engine> make_specular_combine_rtl_engine(const std::string& name) {
  return std::make_unique<SpecularCombineRtlEngine<Model>>(name);
}

}  // namespace tmu::tb
