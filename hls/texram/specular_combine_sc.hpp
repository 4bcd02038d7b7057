// SystemC model of the specular combine (000 §7 eq. 6, §8 eq. 7), the same ports and handshake
// as rtl/texram/tmu_specular_combine.sv. Its arithmetic is the golden texram::specular_combine
// (golden/texram/specular_combine.hpp): per colour channel min(255, D + mul255(E, R)), alpha
// from D. The module adds the clocking: one clocked thread, a registered ready and a two-entry
// output FIFO, so it sustains one colour per clock like the RTL (with a latency of one cycle
// instead of the RTL's two).
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/specular_combine/specular_combine_ports.hpp"
#include "hls/common/one_per_clock.hpp"
#include "hls/common/sc_ports.hpp"
#include "texram/specular_combine.hpp"

namespace tmu::hls {

class SpecularCombineSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(specular_combine)

  SC_HAS_PROCESS(SpecularCombineSc);
  explicit SpecularCombineSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    run_one_per_clock<uint32_t>(
        *this, [this](const uint32_t* c) { out_colour_o.write(c ? *c : 0u); },
        [this] {
          return texram::specular_combine(static_cast<uint32_t>(in_diffuse_i.read()),
                                          static_cast<uint32_t>(in_specular_i.read()),
                                          static_cast<uint32_t>(in_reflectance_i.read()));
        });
  }
};

}  // namespace tmu::hls
