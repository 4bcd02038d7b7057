// Port adapter of the material unit's Verilated models (included by material_block.hpp).
#pragma once

namespace tmu::tb {

template <class Model>
class MaterialRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override {
    const bool sample = item && is_material_sample(*item);
    const bool write = item && !sample;
    constexpr uint32_t kCoordMask = (1u << 24) - 1;
    m.wr_valid_i = write;
    m.wr_op_i = write ? static_cast<uint8_t>(item->f[kMatOp] & 1) : 0;
    m.wr_reg_i = write ? static_cast<uint8_t>(item->f[kMatReg] & 0xF) : 0;
    m.wr_value_i = write ? static_cast<uint16_t>(item->f[kMatValue]) : 0;
    m.wr_table_i = write ? static_cast<uint8_t>(item->f[kMatTable] & 1) : 0;
    m.wr_index_i = write ? static_cast<uint8_t>(item->f[kMatIndex]) : 0;
    m.wr_rgb_i = write ? static_cast<uint32_t>(item->f[kMatRgb]) & 0xFFFFFFu : 0;
    m.in_valid_i = sample;
    m.in_u_i = sample ? static_cast<uint32_t>(item->f[kMatU]) & kCoordMask : 0;
    m.in_v_i = sample ? static_cast<uint32_t>(item->f[kMatV]) & kCoordMask : 0;
    m.in_w_i = sample ? static_cast<uint32_t>(item->f[kMatW]) & kCoordMask : 0;
  }
  bool accepts(const Model& m, const Txn& item) const override {
    return is_material_sample(item) ? m.in_ready_o : m.wr_ready_o;
  }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kMatOutRgb] = m.out_rgb_o;
    return t;
  }
};

template <class Model>
class MaterialRtlEngine : public Engine {
 public:
  explicit MaterialRtlEngine(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    size_t expected = 0;
    for (const Txn& t : items) expected += is_material_sample(t);
    MaterialRtlAdapter<Model> adapter;
    return run_rtl(adapter, items, expected, options);
  }

 private:
  std::string name_;
};

template <class Model>
std::unique_ptr<Engine> make_material_rtl_engine(const std::string& name) {
  return std::make_unique<MaterialRtlEngine<Model>>(name);
}

}  // namespace tmu::tb
