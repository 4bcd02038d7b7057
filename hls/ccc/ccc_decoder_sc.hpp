// SystemC model of the CCC decoder (000 §3, Fig. 5), the same ports and handshake as
// rtl/ccc/tmu_ccc_decoder.sv. Its datapath is the golden texel_index(); the module adds the
// clocking: one clocked thread, a registered ready and a two-entry output FIFO, so it
// sustains one texel per clock like the RTL.
#pragma once

#include <systemc>

#include "ccc/ccc_decoder.hpp"
#include "formats/formats.hpp"
#include "hls/common/small_fifo.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

SC_MODULE(CccDecoderSc) {
  template <int W>
  using uint_t = sc_dt::sc_uint<W>;

  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};

  sc_core::sc_in<bool> clut_valid_i{"clut_valid_i"};
  sc_core::sc_out<bool> clut_ready_o{"clut_ready_o"};
  sc_core::sc_in<uint_t<fmts::kClutIndex.width()>> clut_addr_i{"clut_addr_i"};
  sc_core::sc_in<uint_t<fmts::kRgb888.width()>> clut_rgb_i{"clut_rgb_i"};

  sc_core::sc_in<bool> req_valid_i{"req_valid_i"};
  sc_core::sc_out<bool> req_ready_o{"req_ready_o"};
  sc_core::sc_in<uint_t<fmts::kCccBlock.width()>> req_block_i{"req_block_i"};
  sc_core::sc_in<uint_t<fmts::kCccTexel.width()>> req_texel_i{"req_texel_i"};

  sc_core::sc_out<bool> out_valid_o{"out_valid_o"};
  sc_core::sc_in<bool> out_ready_i{"out_ready_i"};
  sc_core::sc_out<uint_t<fmts::kRgb888.width()>> out_rgb_o{"out_rgb_o"};

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
