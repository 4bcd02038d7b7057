// Port adapter of the CCC decoder's Verilated models (included by ccc_decoder_block.hpp).
#pragma once

namespace tmu::tb {

template <class Model>
class CccDecoderRtlAdapter : public RtlAdapter<Model> {
 public:
  void drive(Model& m, const Txn* item) override {
    const bool write = item && item->f[kDecOp] == kOpClutWrite;
    const bool decode = item && item->f[kDecOp] == kOpDecode;
    m.clut_valid_i = write;
    m.clut_addr_i = write ? static_cast<uint8_t>(item->f[kDecClutAddr]) : 0;
    m.clut_rgb_i = write ? static_cast<uint32_t>(item->f[kDecClutRgb]) : 0;
    m.req_valid_i = decode;
    m.req_block_i = decode ? static_cast<uint32_t>(item->f[kDecBlock]) : 0;
    m.req_texel_i = decode ? static_cast<uint8_t>(item->f[kDecTexel]) : 0;
  }
  bool accepts(const Model& m, const Txn& item) const override {
    return item.f[kDecOp] == kOpClutWrite ? m.clut_ready_o : m.req_ready_o;
  }
  void set_out_ready(Model& m, bool ready) override { m.out_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.out_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[0] = m.out_rgb_o;
    return t;
  }
};

template <class Model>
class CccDecoderRtlEngine : public Engine {
 public:
  explicit CccDecoderRtlEngine(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    size_t expected = 0;
    for (const Txn& t : items) expected += t.f[kDecOp] == kOpDecode;
    CccDecoderRtlAdapter<Model> adapter;
    return run_rtl(adapter, items, expected, options);
  }

 private:
  std::string name_;
};

template <class Model>
std::unique_ptr<Engine> make_ccc_decoder_rtl_engine(const std::string& name) {
  return std::make_unique<CccDecoderRtlEngine<Model>>(name);
}

}  // namespace tmu::tb
