// Port adapter of the normal encoder's Verilated models (included by normal_encoder_block.hpp).
#pragma once

namespace tmu::tb {

template <class Model>
class NormalEncoderRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override {
    m.in_valid_i = item != nullptr;
    m.in_x_i = item ? static_cast<uint16_t>(item->f[kEncX]) : 0;
    m.in_y_i = item ? static_cast<uint16_t>(item->f[kEncY]) : 0;
    m.in_z_i = item ? static_cast<uint16_t>(item->f[kEncZ]) : 0;
  }
  bool accepts(const Model& m, const Txn&) const override { return m.in_ready_o; }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kEncPhi] = m.out_phi_o;
    t.f[kEncTheta] = m.out_theta_o;
    return t;
  }
};

template <class Model>
class NormalEncoderRtlEngine : public Engine {
 public:
  explicit NormalEncoderRtlEngine(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    NormalEncoderRtlAdapter<Model> adapter;
    return run_rtl(adapter, items, items.size(), options);
  }

 private:
  std::string name_;
};

template <class Model>
std::unique_ptr<Engine> make_normal_encoder_rtl_engine(const std::string& name) {
  return std::make_unique<NormalEncoderRtlEngine<Model>>(name);
}

}  // namespace tmu::tb
