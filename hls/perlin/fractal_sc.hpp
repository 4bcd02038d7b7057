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

#include "blocks/fractal/fractal_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"
#include "perlin/noise.hpp"

namespace tmu::hls {

class FractalSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(fractal)

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
    constexpr uint32_t kMask = (1u << formats::kFractalValue.width()) - 1;
    const fx::Format c = formats::kSolidCoord;
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
        out.push(perlin::fractal_sums(perlin::NoiseConfig{}, signed_value(in_u_i.read(), c),
                                      signed_value(in_v_i.read(), c),
                                      signed_value(in_w_i.read(), c)));
        if (shared_) busy = kSharedClocks - 1;
      } else if (busy > 0) {
        --busy;
      }
    }
  }

  bool shared_;
};

}  // namespace tmu::hls
