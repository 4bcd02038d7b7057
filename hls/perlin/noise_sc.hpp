// SystemC model of the procedural noise unit (002 §4.1), the same ports and handshake as
// rtl/perlin/tmu_noise.sv at the default widths (F = S = B = 8, X = 4). Its arithmetic is the
// golden perlin::noise (golden/perlin/noise.hpp: the split, the fade table, the xor-table
// hash, the seven lerps); the module adds the clocking: one clocked thread, a registered ready
// and a two-entry output FIFO, so it sustains one sample per clock like the RTL (with a
// latency of one cycle instead of the RTL's seven).
#pragma once

#include <cstdint>
#include <systemc>

#include "formats/formats.hpp"
#include "hls/common/small_fifo.hpp"
#include "perlin/noise.hpp"

namespace tmu::hls {

class NoiseSc : public sc_core::sc_module {
 public:
  static constexpr int kCoordW = tmu::formats::kSolidCoord.width();
  static constexpr int kNoiseW = tmu::formats::kNoiseValue.width();
  using coord_t = sc_dt::sc_int<kCoordW>;
  using noise_t = sc_dt::sc_uint<kNoiseW>;  // raw SQ0.11 bits

  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};

  sc_core::sc_in<bool> in_valid_i{"in_valid_i"};
  sc_core::sc_out<bool> in_ready_o{"in_ready_o"};
  sc_core::sc_in<coord_t> in_u_i{"in_u_i"};
  sc_core::sc_in<coord_t> in_v_i{"in_v_i"};
  sc_core::sc_in<coord_t> in_w_i{"in_w_i"};

  sc_core::sc_out<bool> out_valid_o{"out_valid_o"};
  sc_core::sc_in<bool> out_ready_i{"out_ready_i"};
  sc_core::sc_out<noise_t> out_p_o{"out_p_o"};

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
        const int32_t p = perlin::noise(perlin::NoiseConfig{}, in_u_i.read().to_int64(),
                                        in_v_i.read().to_int64(), in_w_i.read().to_int64());
        out.push(static_cast<uint32_t>(p) & ((1u << kNoiseW) - 1));
      }
    }
  }
};

}  // namespace tmu::hls
