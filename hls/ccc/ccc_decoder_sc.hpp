// SystemC model of the CCC decoder (000 §3, Fig. 5), the same ports and handshake as
// rtl/ccc/tmu_ccc_decoder.sv. Its datapath is the golden texel_index(); the module adds the
// clocking: one clocked thread, a registered ready and a two-entry output FIFO, so it
// sustains one texel per clock like the RTL.
#pragma once

#include <systemc>

#include "blocks/ccc_decoder/ccc_decoder_ports.hpp"
#include "ccc/ccc_decoder.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

SC_MODULE(CccDecoderSc) {
  TMU_SC_PORTS(ccc_decoder)

  SC_CTOR(CccDecoderSc) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    SmallFifo<uint32_t, 2> out;
    // Not ready in reset: a ready port promises the next edge will take the input, and the
    // edge that leaves reset is spent here.
    clut_ready_o.write(false);
    req_ready_o.write(false);
    out_valid_o.write(false);
    out_rgb_o.write(0);
    wait();
    while (true) {
      clut_ready_o.write(true);
      req_ready_o.write(out.size() <= 1);  // room for one more whatever the output does
      out_valid_o.write(!out.empty());
      out_rgb_o.write(out.empty() ? 0u : out.front());
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      if (req_ready_o.read() && req_valid_i.read()) {
        const uint8_t index = ccc::texel_index(static_cast<uint32_t>(req_block_i.read()),
                                               static_cast<unsigned>(req_texel_i.read()));
        out.push(clut_[index]);
      }
      if (clut_valid_i.read()) {
        clut_[static_cast<uint8_t>(clut_addr_i.read())] = static_cast<uint32_t>(clut_rgb_i.read());
      }
    }
  }

  uint32_t clut_[fmts::kClutEntries] = {};
};

}  // namespace tmu::hls
