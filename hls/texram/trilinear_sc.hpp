// SystemC model of the TEXRAM trilinear unit (000 §2, §5, §6), the same ports (TMU_SC_PORTS:
// tb/blocks/trilinear/trilinear.json) and handshakes as rtl/texram/tmu_trilinear.sv. Its
// datapath is the golden model's (golden/texram/ trilinear.hpp: plan_sample for the addressing,
// levels, weights, border operators, taps and bank access; tap_colour, blend_taps and combine for
// the colour); the module adds the clocking: one clocked thread that, while idle, takes a CLUT
// write or a request; for a request it makes the sample's accesses one after the other (one per
// byte plane, plane p at address + p, each request held until the memory takes it, then its
// response awaited), and loads the result into a one-entry output register. A sample with nothing
// to read makes no access.
//
// It is sequential (several cycles per sample, one access in flight); only the transactions
// and the memory accesses match the RTL, not its timing.
//
// The configuration (cfg_*) is quasi-static: it is read when a request is accepted. The
// internal widths (texram::Widths) are constructor arguments, as the RTL's parameters.
#pragma once

#include <array>
#include <cstdint>
#include <systemc>

#include "blocks/trilinear/trilinear_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "texram/layout.hpp"
#include "texram/trilinear.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class TrilinearSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(trilinear)

  SC_HAS_PROCESS(TrilinearSc);
  TrilinearSc(sc_core::sc_module_name name, const texram::Widths& widths = {})
      : sc_core::sc_module(name), widths_(widths) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    // Reset. Not ready: a ready port promises the next edge takes the input, and the edge
    // that leaves reset is spent here.
    clut_ready_o.write(false);
    req_ready_o.write(false);
    mem_req_valid_o.write(false);
    mem_req_en_o.write(0);
    mem_req_addr_o.write(0);
    out_valid_o.write(false);
    out_rgba_o.write(0);
    out_full_ = false;
    out_rgba_ = 0;
    wait();
    while (true) {
      // Idle: a CLUT write or a request (or both: the write is then ordered first).
      clut_ready_o.write(true);
      req_ready_o.write(true);
      step();
      clut_ready_o.write(false);
      req_ready_o.write(false);
      if (clut_valid_i.read()) {
        clut_[static_cast<uint8_t>(clut_addr_i.read())] = static_cast<uint32_t>(clut_rgba_i.read());
      }
      if (req_valid_i.read()) {
        serve({static_cast<int32_t>(signed_value(req_u_i.read(), fmts::kTexCoord)),
               static_cast<int32_t>(signed_value(req_v_i.read(), fmts::kTexCoord)),
               static_cast<int32_t>(signed_value(req_lambda_i.read(), fmts::kLod)),
               static_cast<uint32_t>(req_shade_i.read())});
      }
    }
  }

  // One clock: present the output register, wait for the edge, and retire the output if it
  // was taken. Reads after it see the inputs from before the edge.
  void step() {
    out_valid_o.write(out_full_);
    out_rgba_o.write(out_rgba_);
    wait();
    if (out_full_ && out_ready_i.read()) out_full_ = false;
  }

  texram::SamplerConfig config() const {
    texram::SamplerConfig c;
    c.kind = static_cast<texram::TexelKind>(cfg_kind_i.read().to_uint());
    c.single_channel = static_cast<int>(cfg_single_channel_i.read().to_uint());
    c.filter = static_cast<texram::Filter>(cfg_filter_i.read().to_uint());
    c.border_u = static_cast<texram::Border>(cfg_border_u_i.read().to_uint());
    c.border_v = static_cast<texram::Border>(cfg_border_v_i.read().to_uint());
    c.border_rgba = static_cast<uint32_t>(cfg_border_rgba_i.read());
    c.combine = static_cast<texram::Combine>(cfg_combine_i.read().to_uint());
    c.constant_rgba = static_cast<uint32_t>(cfg_constant_rgba_i.read());
    c.addressing = static_cast<texram::Addressing>(cfg_addressing_i.read().to_uint());
    c.widths = widths_;
    return c;
  }

  // One access of the eight banks: request (held until taken), then its response. Plane p
  // reads address + p; a bank not read shows 0 + p, as the RTL's address bus does.
  void access(const texram::SamplePlan& plan, int plane, texram::AccessData& data) {
    constexpr int kW = fmts::kBankAddr.width();
    sc_port_t<fmts::kBanks> en = 0;
    sc_port_t<fmts::kBanks* kW> addr = 0;
    for (int b = 0; b < fmts::kBanks; ++b) {
      const auto& a = plan.bank_address[static_cast<size_t>(b)];
      en[b] = a.has_value();
      addr.range((b + 1) * kW - 1, b * kW) = a.value_or(0) + static_cast<uint32_t>(plane);
    }
    mem_req_en_o.write(en);
    mem_req_addr_o.write(addr);
    mem_req_valid_o.write(true);
    do {
      step();
    } while (!mem_req_ready_i.read());
    mem_req_valid_o.write(false);
    do {
      step();
    } while (!mem_resp_valid_i.read());
    const uint64_t bytes = mem_resp_data_i.read().to_uint64();
    for (size_t b = 0; b < fmts::kBanks; ++b) {
      data[b][static_cast<size_t>(plane)] = static_cast<uint8_t>(bytes >> (8 * b));
    }
  }

  void serve(const texram::Request& request) {
    const texram::SamplerConfig c = config();
    const bool four = c.kind == texram::TexelKind::kTrueColour || c.kind == texram::TexelKind::kCcc;
    const texram::Geometry g(static_cast<int>(cfg_log2_w_i.read().to_uint()),
                             static_cast<int>(cfg_log2_h_i.read().to_uint()),
                             four ? fmts::kPlanes : 1, c.kind == texram::TexelKind::kCcc);
    const texram::SamplePlan plan = texram::plan_sample(g, c, request);
    texram::AccessData data{};
    bool reads = false;
    for (const auto& a : plan.bank_address) reads = reads || a.has_value();
    if (reads) {
      for (int p = 0; p < plan.planes; ++p) access(plan, p, data);
    }
    std::array<std::array<uint32_t, 4>, 2> colours{};
    for (size_t j = 0; j < static_cast<size_t>(plan.levels_read); ++j) {
      for (size_t k = 0; k < static_cast<size_t>(plan.taps_per_level); ++k) {
        colours[j][k] = texram::tap_colour(plan.taps[j][k], data, c.kind, c, clut_);
      }
    }
    const uint32_t rgba =
        texram::combine(texram::blend_taps(plan, colours, c.widths), c, request.shade);
    while (out_full_) step();
    out_full_ = true;
    out_rgba_ = rgba;
  }

  texram::Widths widths_;
  texram::Clut32 clut_{};  // a RAM: no reset
  bool out_full_ = false;
  uint32_t out_rgba_ = 0;
};

}  // namespace tmu::hls
