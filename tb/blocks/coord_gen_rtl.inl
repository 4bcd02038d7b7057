// Port adapter of the coordinate generator's Verilated models (included by
// coord_gen_block.hpp).
#pragma once

namespace tmu::tb {

template <class Model>
class CoordGenRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override {
    const bool write = item && item->f[kCgOp] == kCgOpWrite;
    const bool request = item && item->f[kCgOp] == kCgOpRequest;
    m.tw_valid_i = write;
    m.tw_table_i = write ? static_cast<uint8_t>(item->f[kCgTable]) : 0;
    m.tw_addr_i = write ? static_cast<uint8_t>(item->f[kCgAddr]) : 0;
    m.tw_value_i = write ? static_cast<uint16_t>(item->f[kCgValue]) : 0;  // raw bits
    m.in_valid_i = request;
    m.in_phi_i = request ? static_cast<uint16_t>(item->f[kCgPhi]) : 0;
    m.in_theta_i = request ? static_cast<uint8_t>(item->f[kCgTheta]) : 0;
  }
  bool accepts(const Model& m, const Txn& item) const override {
    return item.f[kCgOp] == kCgOpWrite ? m.tw_ready_o : m.in_ready_o;
  }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kCgUn] = m.out_un_o;
    t.f[kCgVn] = m.out_vn_o;
    t.f[kCgUr] = m.out_ur_o;
    t.f[kCgVr] = m.out_vr_o;
    t.f[kCgWr] = m.out_wr_o;
    return t;
  }
};

template <class Model>
class CoordGenRtlEngine : public Engine {
 public:
  explicit CoordGenRtlEngine(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    size_t expected = 0;
    for (const Txn& t : items) expected += t.f[kCgOp] == kCgOpRequest;
    CoordGenRtlAdapter<Model> adapter;
    return run_rtl(adapter, items, expected, options);
  }

 private:
  std::string name_;
};

template <class Model>
std::unique_ptr<Engine> make_coord_gen_rtl_engine(const std::string& name) {
  return std::make_unique<CoordGenRtlEngine<Model>>(name);
}

}  // namespace tmu::tb
