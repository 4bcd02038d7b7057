// SystemC model of the TEXRAM mipmap generator (000 §12, Fig. 14), the same ports and
// handshakes as rtl/texram/tmu_mipgen.sv. Its datapath is the golden streaming model
// (texram::MipgenStream::step: the stages, the sums, the rounding, the replicas and the
// addresses); the module adds the clocking: one clocked thread that takes an input item
// when at most one write is pending (a registered ready: the pending write may be the one
// leaving at this edge), queues the item's writes and sends one write per clock.
//
// The configuration (cfg_*) is the frame format: a driver changes it only between frames, so
// it is read at the first texel of every frame (a new format starts a new stream; every
// partial sum of a frame completes within it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <systemc>
#include <vector>

#include "blocks/mipgen/mipgen_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "texram/mipgen_stream.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class MipgenSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(mipgen)

  SC_HAS_PROCESS(MipgenSc);
  explicit MipgenSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  texram::MipgenConfig format() const {
    texram::MipgenConfig cfg;
    cfg.log2_w = static_cast<int>(cfg_log2_w_i.read());
    cfg.log2_h = static_cast<int>(cfg_log2_h_i.read());
    cfg.interlaced = cfg_interlaced_i.read() != 0;
    cfg.planes = cfg_four_planes_i.read() != 0 ? fmts::kPlanes : 1;
    cfg.plane = static_cast<int>(cfg_plane_i.read());
    return cfg;
  }

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
        // A frame's first texel takes the format on cfg_* (a new one starts a new stream).
        if (!stream || stream->frame_start()) {
          const texram::MipgenConfig cfg = format();
          if (!stream || !(stream->config() == cfg)) stream.emplace(cfg);
        } else if (in_start_i.read()) {
          stream.emplace(format());  // a frame cut short: the position restarts
        }
        stream->step(
            {static_cast<uint8_t>(in_texel_i.read()), static_cast<uint8_t>(in_above_i.read())},
            pending);
      }
    }
  }
};

}  // namespace tmu::hls
