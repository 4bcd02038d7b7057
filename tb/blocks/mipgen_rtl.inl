// Port adapter of the mipmap generator's Verilated models (included by mipgen_block.hpp): the
// input and write channels and the quasi-static frame format.
#pragma once

#include <utility>

#include "formats/formats.hpp"

namespace tmu::tb {

template <class Model>
class MipgenRtlAdapter : public RtlAdapter<Model> {
 public:
  explicit MipgenRtlAdapter(const texram::MipgenConfig& config) : config_(config) {}

  void drive(Model& m, const Txn* item) override {
    m.in_valid_i = item != nullptr;
    m.in_texel_i = item ? static_cast<uint8_t>(item->f[kMipTexel]) : 0;
    m.in_above_i = item ? static_cast<uint8_t>(item->f[kMipAbove]) : 0;
  }
  bool accepts(const Model& m, const Txn&) const override { return m.in_ready_o; }
  void set_out_ready(Model& m, bool ready) override { m.wr_ready_i = ready; }
  bool out_valid(const Model& m) const override { return m.wr_valid_o; }
  Txn out(const Model& m) const override {
    Txn t;
    t.f[kMipLevel] = m.wr_level_o;
    t.f[kMipX] = m.wr_x_o;
    t.f[kMipY] = m.wr_y_o;
    t.f[kMipValue] = m.wr_value_o;
    t.f[kMipBank] = m.wr_bank_o;
    t.f[kMipAddr] = m.wr_addr_o;
    return t;
  }
  // The format is held from before reset.
  void env_drive(Model& m) override {
    m.cfg_log2_w_i = static_cast<uint8_t>(config_.log2_w);
    m.cfg_log2_h_i = static_cast<uint8_t>(config_.log2_h);
    m.cfg_interlaced_i = config_.interlaced;
    m.cfg_four_planes_i = config_.planes == formats::kPlanes;
    m.cfg_plane_i = static_cast<uint8_t>(config_.plane);
  }

 private:
  texram::MipgenConfig config_;
};

template <class Model>
class MipgenRtlEngine : public Engine {
 public:
  MipgenRtlEngine(std::string name, const texram::MipgenConfig& config)
      : name_(std::move(name)), config_(config) {}
  std::string name() const override { return name_; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    MipgenRtlAdapter<Model> adapter(config_);
    return run_rtl(adapter, items, mipgen_golden_writes(config_, items).size(), options);
  }

 private:
  std::string name_;
  texram::MipgenConfig config_;
};

template <class Model>
std::unique_ptr<Engine> make_mipgen_rtl_engine(const std::string& name,
                                               const texram::MipgenConfig& config) {
  return std::make_unique<MipgenRtlEngine<Model>>(name, config);
}

}  // namespace tmu::tb
