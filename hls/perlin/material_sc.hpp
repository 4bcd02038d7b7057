// SystemC model of the material unit (002 §4.2), the same ports and handshake as
// rtl/perlin/tmu_material.sv. Its state and arithmetic are the golden perlin::MaterialUnit
// (golden/perlin/material_unit.hpp: the registers saturate as write_reg() does, table writes
// beyond 127 are ignored, a sample is shade_material() on the registers and tables written
// before it); the module adds the clocking: one clocked thread, a registered ready and a
// two-entry output FIFO. With the pipelined fractal unit it takes a sample every clock; shared
// (one noise unit for the four octaves), one every 4 clocks like the RTL: after a sample its
// ready stays low for three clocks. Latency one cycle (the RTL's: 13 and 17).
//
// Ordering, as the RTL: a sample accepted at an edge is shaded before a write accepted at the
// same edge. The write port is always ready (the RTL's waits for the samples in flight; this
// model has none in flight that could still read the state).
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/material/material_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"
#include "perlin/material_unit.hpp"
#include "perlin/noise.hpp"

namespace tmu::hls {

class MaterialSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(material)

  // Clocks per sample of the shared configuration: one per octave.
  static constexpr int kSharedClocks = perlin::kOctaves;

  SC_HAS_PROCESS(MaterialSc);
  MaterialSc(sc_core::sc_module_name name, bool shared)
      : sc_core::sc_module(name), shared_(shared) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    // Reset restores golden's register defaults (the RTL's reset values); the tables stay
    // zero here and undefined in the RTL until written.
    perlin::MaterialUnit unit;
    SmallFifo<uint32_t, 2> out;
    int busy = 0;  // clocks until the next sample may be taken (shared)
    // Not ready in reset: a ready port promises the next edge will take the input, and the
    // edge that leaves reset is spent here.
    wr_ready_o.write(false);
    in_ready_o.write(false);
    out_valid_o.write(false);
    out_rgb_o.write(0);
    wait();
    while (true) {
      wr_ready_o.write(true);
      in_ready_o.write(busy == 0 && out.size() <= 1);
      out_valid_o.write(!out.empty());
      out_rgb_o.write(out.empty() ? 0u : out.front());
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      if (in_ready_o.read() && in_valid_i.read()) {
        const fx::Format c = formats::kSolidCoord;
        out.push(unit.sample(signed_value(in_u_i.read(), c), signed_value(in_v_i.read(), c),
                             signed_value(in_w_i.read(), c)));
        if (shared_) busy = kSharedClocks - 1;
      } else if (busy > 0) {
        --busy;
      }
      if (wr_ready_o.read() && wr_valid_i.read()) {
        if (wr_op_i.read() != 0) {  // a colour table entry
          unit.write_table(static_cast<uint32_t>(wr_table_i.read()),
                           static_cast<uint32_t>(wr_index_i.read()),
                           static_cast<uint32_t>(wr_rgb_i.read()));
        } else {
          unit.write_reg(static_cast<perlin::MaterialReg>(static_cast<uint32_t>(wr_reg_i.read())),
                         static_cast<uint32_t>(wr_value_i.read()));
        }
      }
    }
  }

  bool shared_;
};

}  // namespace tmu::hls
