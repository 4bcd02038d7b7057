// SystemC model of the clip-map address unit (003), the same ports (TMU_SC_PORTS:
// tb/blocks/clipmap/clipmap.json) and handshakes as rtl/texram/tmu_clipmap.sv. Its datapath is
// the golden model's (golden/clipmap/clipmap.hpp: plan_clip_sample for the substitution, the
// taps and the bank access, load_writes for a load's writes, colour_of for the texels, blend and
// eq. 5); the module adds the clocking and the registers: one clocked thread that, while idle,
// takes a CLUT write, a region write, a load or a request, in that order when several are
// offered (the RTL takes one of them a cycle, in the same order: the harness offers one at a
// time). A request makes its accesses one after the other (one per byte plane, each held until
// the memory takes it, then its response awaited); a load makes its writes (no response).
//
// Sequential, several cycles per item: only the transactions, the memory accesses and the
// counters match the RTL, not its timing.
#pragma once

#include <array>
#include <cstdint>
#include <systemc>

#include "blocks/clipmap/clipmap_ports.hpp"
#include "clipmap/clipmap.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class ClipmapSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(clipmap)

  SC_HAS_PROCESS(ClipmapSc);
  explicit ClipmapSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    // Reset: not ready (the edge that leaves reset is spent here); the regions empty.
    set_ready(false);
    mem_req_valid_o.write(false);
    mem_req_en_o.write(0);
    mem_req_addr_o.write(0);
    mem_req_we_o.write(false);
    mem_req_wdata_o.write(0);
    out_valid_o.write(false);
    out_rgba_o.write(0);
    out_full_ = false;
    regions_ = {};
    wayward_ = substituted_ = conflicts_ = 0;
    write_counters();
    wait();
    while (true) {
      set_ready(true);
      step();
      set_ready(false);
      if (clut_valid_i.read()) {
        clut_[static_cast<uint8_t>(clut_addr_i.read())] = static_cast<uint32_t>(clut_rgba_i.read());
      } else if (region_valid_i.read()) {
        const auto level = static_cast<size_t>(region_level_i.read());
        if (level < regions_.size()) {
          regions_[level] = {
              static_cast<uint32_t>(region_x0_i.read()), static_cast<uint32_t>(region_y0_i.read()),
              static_cast<uint32_t>(region_x1_i.read()), static_cast<uint32_t>(region_y1_i.read())};
        }
      } else if (load_valid_i.read()) {
        load({static_cast<int>(load_level_i.read()), static_cast<uint32_t>(load_x_i.read()),
              static_cast<uint32_t>(load_y_i.read()), static_cast<uint32_t>(load_texel_i.read())});
      } else if (req_valid_i.read()) {
        serve({static_cast<int32_t>(signed_value(req_u_i.read(), fmts::kTexCoord)),
               static_cast<int32_t>(signed_value(req_v_i.read(), fmts::kTexCoord)),
               static_cast<int32_t>(signed_value(req_lambda_i.read(), fmts::kLod)),
               static_cast<uint32_t>(req_shade_i.read())});
      }
    }
  }

  // Every input port is ready while the unit is idle; the first of them offered is taken.
  void set_ready(bool ready) {
    clut_ready_o.write(ready);
    region_ready_o.write(ready);
    load_ready_o.write(ready);
    req_ready_o.write(ready);
  }

  // One clock: present the output register and the counters, wait for the edge, and retire the
  // output if it was taken. Reads after it see the inputs from before the edge.
  void step() {
    out_valid_o.write(out_full_);
    out_rgba_o.write(out_rgba_);
    write_counters();
    wait();
    if (out_full_ && out_ready_i.read()) out_full_ = false;
  }

  void write_counters() {
    stat_wayward_samples_o.write(static_cast<uint32_t>(wayward_));
    stat_substituted_taps_o.write(static_cast<uint32_t>(substituted_));
    stat_conflicts_o.write(static_cast<uint32_t>(conflicts_));
  }

  clipmap::Config config() const {
    clipmap::Config c;
    c.log2_virtual = static_cast<int>(cfg_log2_virtual_i.read().to_uint());
    c.log2_tile = static_cast<int>(cfg_log2_tile_i.read().to_uint());
    texram::SamplerConfig& s = c.sampler;
    s.kind = static_cast<texram::TexelKind>(cfg_kind_i.read().to_uint());
    s.single_channel = static_cast<int>(cfg_single_channel_i.read().to_uint());
    s.filter = static_cast<texram::Filter>(cfg_filter_i.read().to_uint());
    s.border_u = static_cast<texram::Border>(cfg_border_u_i.read().to_uint());
    s.border_v = static_cast<texram::Border>(cfg_border_v_i.read().to_uint());
    s.border_rgba = static_cast<uint32_t>(cfg_border_rgba_i.read());
    s.combine = static_cast<texram::Combine>(cfg_combine_i.read().to_uint());
    s.constant_rgba = static_cast<uint32_t>(cfg_constant_rgba_i.read());
    c.substitution = static_cast<clipmap::Substitution>(cfg_substitution_i.read().to_uint());
    return c;
  }

  // One access of the eight banks, held until the memory takes it.
  void issue(const clipmap::BankAccess& a, bool write, int plane) {
    constexpr int kW = fmts::kBankAddr.width();
    sc_port_t<fmts::kBanks> en = 0;
    sc_port_t<fmts::kBanks* kW> addr = 0;
    sc_port_t<fmts::kBanks* 8> wdata = 0;
    for (int b = 0; b < fmts::kBanks; ++b) {
      const bool on = (a.enable >> b) & 1;
      en[b] = on;
      // Banks left out: a read shows 0 + plane, a write 0 (tb/blocks/clipmap/clip_memory.hpp).
      addr.range((b + 1) * kW - 1, b * kW) = on      ? a.address[static_cast<size_t>(b)]
                                             : write ? 0
                                                     : static_cast<uint32_t>(plane);
      wdata.range(8 * b + 7, 8 * b) = on && write ? a.data[static_cast<size_t>(b)] : 0;
    }
    mem_req_en_o.write(en);
    mem_req_addr_o.write(addr);
    mem_req_we_o.write(write);
    mem_req_wdata_o.write(wdata);
    mem_req_valid_o.write(true);
    do {
      step();
    } while (!mem_req_ready_i.read());
    mem_req_valid_o.write(false);
    mem_req_we_o.write(false);
    mem_req_wdata_o.write(0);
  }

  void load(const clipmap::Load& l) {
    const clipmap::Config c = config();
    int plane = 0;
    for (const clipmap::BankAccess& a : clipmap::load_writes(c.geometry(), l))
      issue(a, true, plane++);
  }

  void serve(const texram::Request& request) {
    const clipmap::Config c = config();
    const clipmap::ClipPlan plan = clipmap::plan_clip_sample(c.geometry(), c, regions_, request);
    texram::AccessData data{};
    int plane = 0;
    for (const clipmap::BankAccess& a : clipmap::read_accesses(plan)) {
      issue(a, false, plane);
      do {
        step();
      } while (!mem_resp_valid_i.read());
      const uint64_t bytes = mem_resp_data_i.read().to_uint64();
      for (size_t b = 0; b < fmts::kBanks; ++b) {
        data[b][static_cast<size_t>(plane)] = static_cast<uint8_t>(bytes >> (8 * b));
      }
      ++plane;
    }
    wayward_ += plan.wayward;
    substituted_ += static_cast<uint64_t>(plan.substituted_taps);
    conflicts_ += static_cast<uint64_t>(plan.conflicts);
    const uint32_t rgba = clipmap::colour_of(plan, data, c, clut_, request.shade);
    while (out_full_) step();
    out_full_ = true;
    out_rgba_ = rgba;
  }

  texram::Clut32 clut_{};  // a RAM: no reset
  clipmap::Regions regions_{};
  bool out_full_ = false;
  uint32_t out_rgba_ = 0;
  uint64_t wayward_ = 0, substituted_ = 0, conflicts_ = 0;
};

}  // namespace tmu::hls
