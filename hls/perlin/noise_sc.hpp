// SystemC model of the procedural noise unit (002 §4.1), the same ports and handshake as
// rtl/perlin/tmu_noise.sv at the default widths (F = S = B = 8, X = 4). Its arithmetic is the
// golden perlin::noise (golden/perlin/noise.hpp: the split, the fade table, the xor-table
// hash, the seven lerps); the module adds the clocking: one clocked thread, a registered ready
// and a two-entry output FIFO, so it sustains one sample per clock like the RTL (with a
// latency of one cycle instead of the RTL's seven).
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/noise/noise_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/one_per_clock.hpp"
#include "hls/common/sc_ports.hpp"
#include "perlin/noise.hpp"

namespace tmu::hls {

class NoiseSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(noise)

  SC_HAS_PROCESS(NoiseSc);
  explicit NoiseSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    run_one_per_clock<uint32_t>(
        *this, [this](const uint32_t* p) { out_p_o.write(p ? *p : 0u); },
        [this] {
          const fx::Format c = formats::kSolidCoord;
          const int32_t p =
              perlin::noise(perlin::NoiseConfig{}, signed_value(in_u_i.read(), c),
                            signed_value(in_v_i.read(), c), signed_value(in_w_i.read(), c));
          return static_cast<uint32_t>(p) & ((1u << formats::kNoiseValue.width()) - 1);
        });
  }
};

}  // namespace tmu::hls
