// SystemC model of the TEXRAM's video port receiver (000 §11), the same ports and handshakes
// as rtl/texram/tmu_video_port.sv. Its checks are the golden receiver's
// (texram::video::VideoReceiver: the flags of each place, the source order, the dropped frames
// and field-order errors); the module adds the clocking: one clocked thread with a registered
// ready and a two-entry output FIFO, one item per clock. The format on cfg_* is compared with
// the receiver's at every clock, and a new one is taken with set_format (a frame under way is
// dropped and counted), as the RTL does.
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/video_port/video_port_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"
#include "texram/video/video_port.hpp"

namespace tmu::hls {

class VideoPortSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(video_port)

  SC_HAS_PROCESS(VideoPortSc);
  explicit VideoPortSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  struct Out {
    texram::video::Received r;
    uint32_t texel = 0;
  };

  texram::video::VideoFormat format() const {
    texram::video::VideoFormat f;
    f.log2_w = static_cast<int>(cfg_log2_w_i.read());
    f.log2_h = static_cast<int>(cfg_log2_h_i.read());
    f.interlaced = cfg_interlaced_i.read() != 0;
    f.planes = cfg_four_planes_i.read() != 0 ? formats::kPlanes : 1;
    return f;
  }

  void show(const Out* o) {
    out_valid_o.write(o != nullptr);
    out_accepted_o.write(o && o->r.accepted);
    out_x_o.write(o ? o->r.x : 0u);
    out_y_o.write(o ? o->r.y : 0u);
    out_frame_start_o.write(o && o->r.frame_start);
    out_frame_end_o.write(o && o->r.frame_end);
    out_dropped_o.write(o && o->r.dropped);
    out_error_o.write(o ? static_cast<unsigned>(o->r.error) : 0u);
    out_texel_o.write(o ? o->texel : 0u);
  }

  // The ports keep the counts' low 32 bits: the RTL's registers wrap.
  void write_stats(const texram::video::ReceiverStats& s) {
    stat_items_o.write(s.items);
    stat_frames_complete_o.write(s.frames_complete);
    stat_frames_dropped_o.write(s.frames_dropped);
    stat_items_discarded_o.write(s.items_discarded);
    stat_field_order_errors_o.write(s.field_order_errors);
  }

  void run() {
    // The RTL resets its registered format to all zeros: a 1 x 1 progressive one-plane video.
    texram::video::VideoReceiver rx{texram::video::VideoFormat{}};
    SmallFifo<Out, 2> out;
    in_ready_o.write(false);  // the edge that leaves reset is spent here
    show(nullptr);
    write_stats(rx.stats());
    wait();
    while (true) {
      in_ready_o.write(out.size() <= 1);
      show(out.empty() ? nullptr : &out.front());
      write_stats(rx.stats());
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      const texram::video::VideoFormat f = format();
      if (!(f == rx.format())) rx.set_format(f);
      if (in_ready_o.read() && in_valid_i.read()) {
        texram::video::VideoItem item;
        item.flags = static_cast<uint8_t>(in_flags_i.read());
        const auto texel = static_cast<uint32_t>(in_texel_i.read());
        Out o;
        o.r = rx.step(item);
        o.texel = f.planes == 1 ? texel & 0xFF00'0000u : texel;
        out.push(o);
      }
    }
  }
};

}  // namespace tmu::hls
