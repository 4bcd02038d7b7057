// Port adapters of the noise unit's and the fractal sums' Verilated models (included by
// perlin_block.hpp).
#pragma once

namespace tmu::tb {

namespace perlin_rtl {
inline constexpr uint32_t kCoordMask = (1u << 24) - 1;  // SolidCoord's 24 bits

template <class Model>
void drive_coords(Model& m, const Txn* item) {
  m.in_valid_i = item != nullptr;
  m.in_u_i = item ? static_cast<uint32_t>(item->f[kSolidU]) & kCoordMask : 0;
  m.in_v_i = item ? static_cast<uint32_t>(item->f[kSolidV]) & kCoordMask : 0;
  m.in_w_i = item ? static_cast<uint32_t>(item->f[kSolidW]) & kCoordMask : 0;
}
}  // namespace perlin_rtl

template <class Model>
class PerlinRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override { perlin_rtl::drive_coords(m, item); }
  bool accepts(const Model& m, const Txn&) const override { return m.in_ready_o; }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kPerlinP] = m.out_p_o;
    return t;
  }
};

template <class Model>
class TurbulenceRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override { perlin_rtl::drive_coords(m, item); }
  bool accepts(const Model& m, const Txn&) const override { return m.in_ready_o; }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kTurbSum] = m.out_sum_o;
    t.f[kTurbTurbulence] = m.out_turbulence_o;
    return t;
  }
};

template <class Model, template <class> class Adapter>
class PerlinRtlEngine : public Engine {
 public:
  explicit PerlinRtlEngine(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    Adapter<Model> adapter;
    return run_rtl(adapter, items, items.size(), options);
  }

 private:
  std::string name_;
};

template <class Model>
std::unique_ptr<Engine> make_perlin_rtl_engine(const std::string& name) {
  return std::make_unique<PerlinRtlEngine<Model, PerlinRtlAdapter>>(name);
}

template <class Model>
std::unique_ptr<Engine> make_turbulence_rtl_engine(const std::string& name) {
  return std::make_unique<PerlinRtlEngine<Model, TurbulenceRtlAdapter>>(name);
}

}  // namespace tmu::tb
