// SystemC model of the TEXRAM mipmap generator (000 §12, Fig. 14), the same ports and
// handshakes as rtl/texram/tmu_mipgen.sv. Its datapath is the golden streaming model
// (texram::MipgenStream::step: the stages, the sums, the rounding, the replicas and the
// addresses); the module adds the clocking: one clocked thread that takes an input item
// when at most one write is pending (a registered ready: the pending write may be the one
// leaving at this edge), queues the item's writes and sends one write per clock.
//
// The configuration (cfg_*) is quasi-static: it is read when the first item is accepted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <systemc>
#include <vector>

#include "formats/formats.hpp"
#include "texram/mipgen_stream.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

SC_MODULE(MipgenSc) {
  template <int W>
  using uint_t = sc_dt::sc_uint<W>;

  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};

  sc_core::sc_in<uint_t<fmts::kMipLog2.width()>> cfg_log2_w_i{"cfg_log2_w_i"};
  sc_core::sc_in<uint_t<fmts::kMipLog2.width()>> cfg_log2_h_i{"cfg_log2_h_i"};
  sc_core::sc_in<bool> cfg_interlaced_i{"cfg_interlaced_i"};
  sc_core::sc_in<bool> cfg_four_planes_i{"cfg_four_planes_i"};
  sc_core::sc_in<uint_t<fmts::kBytePlane.width()>> cfg_plane_i{"cfg_plane_i"};

  sc_core::sc_in<bool> in_valid_i{"in_valid_i"};
  sc_core::sc_out<bool> in_ready_o{"in_ready_o"};
  sc_core::sc_in<uint_t<fmts::kChannel.width()>> in_texel_i{"in_texel_i"};
  sc_core::sc_in<uint_t<fmts::kChannel.width()>> in_above_i{"in_above_i"};

  sc_core::sc_out<bool> wr_valid_o{"wr_valid_o"};
  sc_core::sc_in<bool> wr_ready_i{"wr_ready_i"};
  sc_core::sc_out<uint_t<fmts::kMipLevel.width()>> wr_level_o{"wr_level_o"};
  sc_core::sc_out<uint_t<fmts::kMipCoord.width()>> wr_x_o{"wr_x_o"};
  sc_core::sc_out<uint_t<fmts::kMipCoord.width()>> wr_y_o{"wr_y_o"};
  sc_core::sc_out<uint_t<fmts::kChannel.width()>> wr_value_o{"wr_value_o"};
  sc_core::sc_out<uint_t<fmts::kBank.width()>> wr_bank_o{"wr_bank_o"};
  sc_core::sc_out<uint_t<fmts::kBankAddr.width()>> wr_addr_o{"wr_addr_o"};

  SC_CTOR(MipgenSc) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void present(const texram::CellWrite* w) {
    wr_valid_o.write(w != nullptr);
    wr_level_o.write(w ? static_cast<unsigned>(w->level) : 0u);
    wr_x_o.write(w ? w->x : 0u);
    wr_y_o.write(w ? w->y : 0u);
    wr_value_o.write(w ? w->value : 0u);
    wr_bank_o.write(w ? w->cell.bank : 0u);
    wr_addr_o.write(w ? w->cell.address : 0u);
  }

  void run() {
    // Reset. Not ready: a ready port promises the next edge takes the input, and the edge
    // that leaves reset is spent here.
    in_ready_o.write(false);
    present(nullptr);
    std::optional<texram::MipgenStream> stream;
    std::vector<texram::CellWrite> pending;  // the writes still to send, pending[head] first
    size_t head = 0;
    wait();
    while (true) {
      in_ready_o.write(pending.size() - head <= 1);
      present(head < pending.size() ? &pending[head] : nullptr);
      wait();
      // Everything below sees the values from before this edge.
      if (wr_valid_o.read() && wr_ready_i.read()) ++head;
      if (head == pending.size() || head >= 4096) {  // drop what has been sent
        pending.erase(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(head));
        head = 0;
      }
      if (in_ready_o.read() && in_valid_i.read()) {
        if (!stream) {
          texram::MipgenConfig cfg;
          cfg.log2_w = static_cast<int>(cfg_log2_w_i.read());
          cfg.log2_h = static_cast<int>(cfg_log2_h_i.read());
          cfg.interlaced = cfg_interlaced_i.read();
          cfg.planes = cfg_four_planes_i.read() ? fmts::kPlanes : 1;
          cfg.plane = static_cast<int>(cfg_plane_i.read());
          stream.emplace(cfg);
        }
        stream->step(
            {static_cast<uint8_t>(in_texel_i.read()), static_cast<uint8_t>(in_above_i.read())},
            pending);
      }
    }
  }
};

}  // namespace tmu::hls
