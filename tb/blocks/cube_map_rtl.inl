// Port adapter of the cube map addressing unit's Verilated models (included by
// cube_map_block.hpp).
#pragma once

namespace tmu::tb {

template <class Model>
class CubeMapRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override {
    m.in_valid_i = item != nullptr;
    m.in_x_i = item ? static_cast<uint16_t>(item->f[kCubeX]) : 0;
    m.in_y_i = item ? static_cast<uint16_t>(item->f[kCubeY]) : 0;
    m.in_z_i = item ? static_cast<uint16_t>(item->f[kCubeZ]) : 0;
    m.in_face_log2_i = item ? static_cast<uint8_t>(item->f[kCubeLog2]) : 0;
  }
  bool accepts(const Model& m, const Txn&) const override { return m.in_ready_o; }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    constexpr uint64_t kCoordMask = (uint64_t{1} << formats::kTexCoord.width()) - 1;
    Txn t;
    t.f[kCubeFace] = m.out_face_o;
    t.f[kCubeU] = m.out_u_o & kCoordMask;
    t.f[kCubeV] = m.out_v_o & kCoordMask;
    return t;
  }
};

template <class Model>
class CubeMapRtlEngine : public Engine {
 public:
  explicit CubeMapRtlEngine(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    CubeMapRtlAdapter<Model> adapter;
    return run_rtl(adapter, items, items.size(), options);
  }

 private:
  std::string name_;
};

template <class Model>
std::unique_ptr<Engine> make_cube_map_rtl_engine(const std::string& name) {
  return std::make_unique<CubeMapRtlEngine<Model>>(name);
}

}  // namespace tmu::tb
