// SystemC model of the TEXRAM's volume unit (000 §13, Fig. 15; docs/volume.md), the same ports
// (TMU_SC_PORTS: tb/blocks/volume/volume.json) and handshakes as rtl/volume/tmu_volume.sv. Its
// arithmetic is the golden model's: the marcher (volume::Marcher), the access plan of a
// location (volume::plan_accesses: the schedule and the layout's cells) and the blends from the
// bytes the memory port brought back (volume::blend). The module adds the clocking: one clocked
// thread that, while idle, takes a ray; per location it presents the plan's accesses one per
// clock (each held until the memory takes it), gathers the responses as they come, blends
// when the last is in, and loads a one-entry output register (waiting while it is full).
//
// It is sequential per location (the next location's first access waits for the last
// response of the one before, one clock more per location than the RTL with page hits, and a
// clock between rays); the transactions, every memory access and the counters match the RTL,
// not its timing.
#pragma once

#include <array>
#include <cstdint>
#include <systemc>
#include <vector>

#include "blocks/volume/volume_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "volume/layout.hpp"
#include "volume/marcher.hpp"
#include "volume/unit.hpp"

namespace tmu::hls {

SC_MODULE(VolumeSc) {
  TMU_SC_PORTS(volume)

  SC_CTOR(VolumeSc) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  static constexpr int kPosW = formats::kVoxelPos.width();
  static constexpr int kStepW = formats::kVoxelStep.width();
  static constexpr int kSizeW = formats::kVolumeSize.width();
  static constexpr int kAddrW = formats::kBankAddr.width();
  static constexpr int kGradW = formats::kVolumeGrad.width();

  void run() {
    // Not ready in reset: a ready port promises the next edge takes the input, and the edge
    // that leaves reset is spent here.
    ray_ready_o.write(false);
    mem_req_valid_o.write(false);
    mem_req_en_o.write(0);
    mem_req_addr_o.write(0);
    out_full_ = false;
    rays_ = resamples_ = 0;
    show();
    wait();
    while (true) {
      ray_ready_o.write(true);
      step();
      ray_ready_o.write(false);
      if (ray_valid_i.read()) serve(read_ray());
    }
  }

  // One clock: present the output register and the counters, wait for the edge, retire the
  // output if it was taken. Reads after it see the inputs from before the edge.
  void step() {
    show();
    wait();
    if (out_full_ && out_ready_i.read()) out_full_ = false;
  }

  void show() {
    out_valid_o.write(out_full_);
    out_value_o.write(out_.value);
    sc_port_t<3 * kGradW> grad = 0;
    for (int a = 0; a < 3; ++a) {
      grad.range((a + 1) * kGradW - 1, a * kGradW) =
          static_cast<uint32_t>(out_.gradient[static_cast<size_t>(a)]) & ((1u << kGradW) - 1);
    }
    out_grad_o.write(grad);
    out_last_o.write(out_last_ ? 1 : 0);
    stat_rays_o.write(rays_);
    stat_resamples_o.write(resamples_);
  }

  volume::Ray read_ray() {
    ++rays_;
    volume::Ray r;
    const auto start = ray_start_i.read();
    const auto step = ray_step_i.read();
    for (int a = 0; a < 3; ++a) {
      r.start[static_cast<size_t>(a)] = static_cast<int32_t>(signed_value(
          sc_port_t<kPosW>(start.range((a + 1) * kPosW - 1, a * kPosW)), formats::kVoxelPos));
      r.step[static_cast<size_t>(a)] = static_cast<int32_t>(signed_value(
          sc_port_t<kStepW>(step.range((a + 1) * kStepW - 1, a * kStepW)), formats::kVoxelStep));
    }
    r.count = static_cast<uint32_t>(ray_count_i.read());
    return r;
  }

  void serve(const volume::Ray& ray) {
    const auto size = cfg_size_i.read();
    const volume::VolumeGeometry geometry(
        static_cast<uint32_t>(size.range(kSizeW - 1, 0)),
        static_cast<uint32_t>(size.range(2 * kSizeW - 1, kSizeW)),
        static_cast<uint32_t>(size.range(3 * kSizeW - 1, 2 * kSizeW)));
    const volume::Config config{cfg_mode_i.read() != 0 ? volume::Mode::kRaw : volume::Mode::kValue,
                                static_cast<int>(cfg_weight_bits_i.read())};
    for (volume::Marcher m(ray); !m.done(); m.advance()) {
      const volume::Position pos = m.position();
      const std::vector<volume::Access> plan = volume::plan_accesses(geometry, pos, config.mode);
      const std::vector<volume::AccessData> data = accesses(plan);
      const volume::Resample r = volume::blend(geometry, config, pos, plan, data);
      while (out_full_) step();
      out_full_ = true;
      out_ = r;
      out_last_ = m.index() + 1 == ray.count;
      ++resamples_;
    }
  }

  // The plan's accesses, one per clock while the memory takes them, and their responses as
  // they come (in order). A bank that idles shows address 0, as the RTL's bus does.
  std::vector<volume::AccessData> accesses(const std::vector<volume::Access>& plan) {
    std::vector<volume::AccessData> data(plan.size());
    size_t issued = 0, received = 0;
    while (received < plan.size()) {
      const bool presenting = issued < plan.size();
      if (presenting) present(plan[issued]);
      mem_req_valid_o.write(presenting);
      step();
      if (presenting && mem_req_ready_i.read()) ++issued;
      if (mem_resp_valid_i.read()) {
        const uint64_t bytes = mem_resp_data_i.read().to_uint64();
        for (size_t b = 0; b < volume::kVolumeBanks; ++b) {
          data[received][b] = static_cast<uint8_t>(bytes >> (8 * b));
        }
        ++received;
      }
    }
    mem_req_valid_o.write(false);
    return data;
  }

  void present(const volume::Access& access) {
    sc_port_t<formats::kBanks> en = 0;
    sc_port_t<formats::kBanks* kAddrW> addr = 0;
    for (size_t b = 0; b < volume::kVolumeBanks; ++b) {
      const int lo = static_cast<int>(b) * kAddrW;
      en[static_cast<int>(b)] = access.address[b].has_value();
      addr.range(lo + kAddrW - 1, lo) = access.address[b].value_or(0);
    }
    mem_req_en_o.write(en);
    mem_req_addr_o.write(addr);
  }

  bool out_full_ = false;
  volume::Resample out_;
  bool out_last_ = false;
  uint32_t rays_ = 0, resamples_ = 0;
};

}  // namespace tmu::hls
