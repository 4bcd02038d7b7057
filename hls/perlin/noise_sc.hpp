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
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"
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
    SmallFifo<uint32_t, 2> out;
    // Not ready in reset: a ready port promises the next edge will take the input, and the
    // edge that leaves reset is spent here.
    in_ready_o.write(false);
    out_valid_o.write(false);
    out_p_o.write(0);
    wait();
    while (true) {
      in_ready_o.write(out.size() <= 1);  // room for one more whatever the output does
      out_valid_o.write(!out.empty());
      out_p_o.write(out.empty() ? 0u : out.front());
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      if (in_ready_o.read() && in_valid_i.read()) {
        const fx::Format c = formats::kSolidCoord;
        const int32_t p =
            perlin::noise(perlin::NoiseConfig{}, signed_value(in_u_i.read(), c),
                          signed_value(in_v_i.read(), c), signed_value(in_w_i.read(), c));
        out.push(static_cast<uint32_t>(p) & ((1u << formats::kNoiseValue.width()) - 1));
      }
    }
  }
};

}  // namespace tmu::hls
