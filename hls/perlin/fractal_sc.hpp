// SystemC model of the fractal sums of four octaves (002 §4.1.1), the same ports and handshake
// as rtl/perlin/tmu_fractal_pipelined.sv and rtl/perlin/tmu_fractal_shared.sv at the default
// widths. Its arithmetic is the golden perlin::fractal_sums (golden/perlin/noise.hpp); the
// module adds the clocking: one clocked thread, a registered ready and a two-entry output
// FIFO. Pipelined (the default), it takes a sample every clock; shared (the thesis's one noise
// unit for the four octaves), it takes one every 4 clocks like tmu_fractal_shared: after a
// sample its ready stays low for three clocks. Latency one cycle (the RTL's: 8 and 12).
#pragma once

#include <cstdint>
#include <systemc>

#include "formats/formats.hpp"
#include "hls/common/small_fifo.hpp"
#include "perlin/noise.hpp"

namespace tmu::hls {

class FractalSc : public sc_core::sc_module {
 public:
  static constexpr int kCoordW = tmu::formats::kSolidCoord.width();
  static constexpr int kSumW = tmu::formats::kFractalValue.width();
  using coord_t = sc_dt::sc_int<kCoordW>;
  using sum_t = sc_dt::sc_uint<kSumW>;  // raw SQ2.14 bits

  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};

  sc_core::sc_in<bool> in_valid_i{"in_valid_i"};
  sc_core::sc_out<bool> in_ready_o{"in_ready_o"};
  sc_core::sc_in<coord_t> in_u_i{"in_u_i"};
  sc_core::sc_in<coord_t> in_v_i{"in_v_i"};
  sc_core::sc_in<coord_t> in_w_i{"in_w_i"};

  sc_core::sc_out<bool> out_valid_o{"out_valid_o"};
  sc_core::sc_in<bool> out_ready_i{"out_ready_i"};
  sc_core::sc_out<sum_t> out_sum_o{"out_sum_o"};
  sc_core::sc_out<sum_t> out_turbulence_o{"out_turbulence_o"};

  // Clocks per sample of the shared configuration: one per octave.
  static constexpr int kSharedClocks = perlin::kOctaves;

  SC_HAS_PROCESS(FractalSc);
  FractalSc(sc_core::sc_module_name name, bool shared) : sc_core::sc_module(name), shared_(shared) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    SmallFifo<perlin::FractalSums, 2> out;
    int busy = 0;  // clocks until the next sample may be taken (shared)
    in_ready_o.write(false);
    out_valid_o.write(false);
    out_sum_o.write(0);
    out_turbulence_o.write(0);
    wait();
    constexpr uint32_t kMask = (1u << kSumW) - 1;
    while (true) {
      in_ready_o.write(busy == 0 && out.size() <= 1);
      out_valid_o.write(!out.empty());
      out_sum_o.write(out.empty() ? 0u : static_cast<uint32_t>(out.front().fractal_sum) & kMask);
      out_turbulence_o.write(out.empty() ? 0u
                                         : static_cast<uint32_t>(out.front().turbulence) & kMask);
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      if (in_ready_o.read() && in_valid_i.read()) {
        out.push(perlin::fractal_sums(perlin::NoiseConfig{}, in_u_i.read().to_int64(),
                                      in_v_i.read().to_int64(), in_w_i.read().to_int64()));
        if (shared_) busy = kSharedClocks - 1;
      } else if (busy > 0) {
        --busy;
      }
    }
  }

  bool shared_;
};

}  // namespace tmu::hls
