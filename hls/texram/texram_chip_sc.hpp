// SystemC model of the TEXRAM chip (000 §14; docs/texram_chip.md), the same ports (TMU_SC_PORTS:
// tb/blocks/texram_chip/texram_chip.json) and handshakes as rtl/texram/tmu_texram_chip.sv. Its
// datapath is the golden model's: the DRF write decode (texram::chip::apply), the sequencer's
// walk and registers as golden texram::chip::TexramChip::pixel, each step's sample by golden's
// texram::chip::sample_step (texram/chip/chip_step.hpp: footprint probes, detail maps, the
// trilinear arithmetic at base + the layout's address) with this module as its memory reader,
// eq. 6-7 by specular_combine. The module adds the clocking: one clocked thread that,
// while idle, takes a DRF write, a CLUT write or a pixel's first parameter (in that order when
// several come together); a pixel then takes its further parameters from the same port when a
// DRF asks, makes each sample's accesses one after the other (held until the memory takes it,
// then its response awaited), and loads emitted samples and the colour into a one-entry output
// register.
//
// It is sequential (several cycles per step, one access in flight); only the transactions, the
// memory accesses and the counters match the RTL, not its timing.
#pragma once

#include <array>
#include <cstdint>
#include <systemc>

#include "blocks/texram_chip/texram_chip_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "texram/chip/chip_step.hpp"
#include "texram/chip/drf.hpp"
#include "texram/chip/texram_chip.hpp"
#include "texram/trilinear.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class TexramChipSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(texram_chip)

  SC_HAS_PROCESS(TexramChipSc);
  explicit TexramChipSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  using Drf = texram::chip::Drf;

  using Param = texram::chip::PixelParameter;

  void run() {
    // Reset. Not ready: the edge that leaves reset is spent here.
    drf_ready_o.write(false);
    clut_ready_o.write(false);
    param_ready_o.write(false);
    mem_req_valid_o.write(false);
    mem_req_en_o.write(0);
    mem_req_addr_o.write(0);
    out_valid_o.write(false);
    out_rgba_o.write(0);
    out_last_o.write(0);
    drfs_ = {};
    out_full_ = false;
    out_rgba_ = 0;
    out_last_ = false;
    pixels_ = params_ = steps_ = 0;
    step_limit_ = false;
    write_stats();
    wait();
    while (true) {
      drf_ready_o.write(true);
      clut_ready_o.write(true);
      param_ready_o.write(true);
      step();
      drf_ready_o.write(false);
      clut_ready_o.write(false);
      param_ready_o.write(false);
      if (drf_valid_i.read()) {
        texram::chip::apply(drfs_, {static_cast<uint8_t>(drf_drf_i.read().to_uint()),
                                    static_cast<uint8_t>(drf_field_i.read().to_uint()),
                                    static_cast<uint32_t>(drf_value_i.read())});
      }
      if (clut_valid_i.read()) {
        clut_[static_cast<uint8_t>(clut_addr_i.read())] = static_cast<uint32_t>(clut_rgba_i.read());
      }
      if (param_valid_i.read()) pixel(read_param());
    }
  }

  // One clock: present the output register and the counters, wait for the edge, and retire the
  // output if it was taken. Reads after it see the inputs from before the edge.
  void step() {
    out_valid_o.write(out_full_);
    out_rgba_o.write(out_rgba_);
    out_last_o.write(out_last_);
    write_stats();
    wait();
    if (out_full_ && out_ready_i.read()) out_full_ = false;
  }

  void write_stats() {
    stat_pixels_o.write(pixels_);
    stat_parameters_o.write(params_);
    stat_steps_o.write(steps_);
    stat_step_limit_o.write(step_limit_ ? 1 : 0);
  }

  Param read_param() {
    ++params_;
    Param p;
    p.lead = static_cast<int>(param_lead_i.read().to_uint());
    p.request = {static_cast<int32_t>(signed_value(param_u_i.read(), fmts::kTexCoord)),
                 static_cast<int32_t>(signed_value(param_v_i.read(), fmts::kTexCoord)),
                 static_cast<int32_t>(signed_value(param_lambda_i.read(), fmts::kLod)),
                 static_cast<uint32_t>(param_shade_i.read())};
    p.r1u = static_cast<int32_t>(signed_value(param_r1u_i.read(), fmts::kTexDeriv));
    p.r1v = static_cast<int32_t>(signed_value(param_r1v_i.read(), fmts::kTexDeriv));
    p.r2u = static_cast<int32_t>(signed_value(param_r2u_i.read(), fmts::kTexDeriv));
    p.r2v = static_cast<int32_t>(signed_value(param_r2v_i.read(), fmts::kTexDeriv));
    p.face = static_cast<int>(param_face_i.read().to_uint());
    return p;
  }

  // The pixel's next parameter, from the same port.
  Param take_param() {
    param_ready_o.write(true);
    do {
      step();
    } while (!param_valid_i.read());
    param_ready_o.write(false);
    return read_param();
  }

  void emit(uint32_t rgba, bool last) {
    while (out_full_) step();
    out_full_ = true;
    out_rgba_ = rgba;
    out_last_ = last;
  }

  // golden TexramChip::pixel, with the parameters from the port.
  void pixel(Param p) {
    ++pixels_;
    texram::chip::PixelRegisters regs;
    regs.shade = p.request.shade;
    const texram::chip::StepContext context{drfs_, clut_, reader_};
    int number = p.lead & 7;
    for (int step = 0; number != 0; ++step) {
      if (step >= texram::chip::kMaxSteps) {
        step_limit_ = true;
        break;
      }
      const Drf& d = drfs_[static_cast<size_t>(number - 1)];
      if (step > 0 && d.takes_coords) {
        p = take_param();
        regs.take_parameter(d, p.request.shade);
      }
      ++steps_;
      const uint32_t s = texram::chip::sample_step(context, number, p, regs.shade);
      if (regs.apply(d, s)) emit(s, false);
      int extra = 0;
      number = texram::chip::next_drf(drfs_, d, &extra);
      step += extra;
      steps_ += static_cast<uint32_t>(extra);
    }
    emit(regs.result(), true);
  }

  // One access of the eight banks at the map's base: request (held until taken), then its
  // response. A bank not read shows address 0, as the RTL's bus does.
  void access(const texram::SamplePlan& plan, uint32_t base, int plane, texram::AccessData& data) {
    constexpr int kW = fmts::kBankAddr.width();
    sc_port_t<fmts::kBanks> en = 0;
    sc_port_t<fmts::kBanks* kW> addr = 0;
    for (int b = 0; b < fmts::kBanks; ++b) {
      const auto& a = plan.bank_address[static_cast<size_t>(b)];
      en[b] = a.has_value();
      addr.range((b + 1) * kW - 1, b * kW) =
          a ? (base + *a + static_cast<uint32_t>(plane)) & ((1u << kW) - 1) : 0u;
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

  // golden's sample_step reads the maps through this: each plane one clocked access.
  struct Reader : texram::chip::ChipReader {
    explicit Reader(TexramChipSc& chip) : chip_(chip) {}
    void read(int, uint32_t base, const texram::SamplePlan& plan,
              texram::AccessData& data) override {
      for (int plane = 0; plane < plan.planes; ++plane) chip_.access(plan, base, plane, data);
    }
    TexramChipSc& chip_;
  };

  texram::chip::DrfFile drfs_{};
  texram::Clut32 clut_{};  // a RAM: no reset
  Reader reader_{*this};
  bool out_full_ = false;
  uint32_t out_rgba_ = 0;
  bool out_last_ = false;
  uint32_t pixels_ = 0, params_ = 0, steps_ = 0;
  bool step_limit_ = false;
};

}  // namespace tmu::hls
