// SystemC model of the TEXRAM's video unit (000 §11-12), the same ports and handshakes as
// rtl/texram/tmu_video_unit.sv. Its port, generators, row buffers, reads of the line above and
// swaps are the golden model's (texram::video::VideoUnit at rows of `cells`, 8 or 512, 8 buffers
// a bank); the module adds the clocking and the memory: one clocked thread that takes an in item
// in one clock, and a cycle item (one memory cycle) when its two-entry output FIFO has room, with
// a registered ready. The cycle's access goes out on mem_req as the row's 8-cell words, one a
// clock; a read's next word goes when the last one's cells are back on mem_resp. The thread
// takes no item until the access is out and a read's row is back, which it hands to the golden
// model (external_reads). cfg_* are read at every clock: a new format or new bases start a new
// video map, new bounds take effect at the next cycle.
#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <systemc>
#include <vector>

#include "blocks/video_unit/video_unit_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"
#include "texram/video/video_unit.hpp"

namespace tmu::hls {

class VideoUnitSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(video_unit)

  SC_HAS_PROCESS(VideoUnitSc);
  VideoUnitSc(sc_core::sc_module_name name, uint32_t cells)
      : sc_core::sc_module(name), cells_(cells) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  static constexpr uint32_t kWordCells = 8;  // the memory port's word
  const uint32_t cells_;
  using Unit = texram::video::VideoUnit;
  using Access = texram::video::RowBuffers::Access;

  struct Out {
    bool granted = false, write = false, read = false, fault = false, swap = false, front = false;
    uint32_t wait = 0;
  };

  void show(const Out* o) {
    out_valid_o.write(o != nullptr);
    out_granted_o.write(o && o->granted);
    out_write_o.write(o && o->write);
    out_read_o.write(o && o->read);
    out_fault_o.write(o && o->fault);
    out_wait_o.write(o ? o->wait : 0u);
    out_swap_o.write(o && o->swap);
    out_front_o.write(o && o->front);
  }

  // The ports keep the counts' low 32 bits: the RTL's registers wrap.
  void write_stats(const Unit& unit) {
    const Unit::Counts c = unit.counts();
    stat_frames_shown_o.write(c.shown);
    stat_frames_dropped_o.write(c.dropped);
    stat_overruns_o.write(c.overruns);
    stat_late_reads_o.write(c.late_reads);
    stat_lost_writes_o.write(c.lost_writes);
    stat_forced_o.write(c.forced);
  }

  texram::video::VideoMapConfig config() const {
    texram::video::VideoMapConfig c;
    c.format.log2_w = static_cast<int>(cfg_log2_w_i.read());
    c.format.log2_h = static_cast<int>(cfg_log2_h_i.read());
    c.format.interlaced = cfg_interlaced_i.read() != 0;
    c.format.planes = cfg_four_planes_i.read() != 0 ? formats::kPlanes : 1;
    c.base = static_cast<uint32_t>(cfg_base0_i.read());
    c.base1 = static_cast<uint32_t>(cfg_base1_i.read());
    c.arbiter.segment_cells = cells_;
    c.arbiter.buffers_per_bank = 8;
    c.arbiter.max_wait = static_cast<uint32_t>(cfg_max_wait_i.read());
    c.arbiter.read_wait = static_cast<uint32_t>(cfg_read_wait_i.read());
    c.external_reads = true;
    return c;
  }

  // Word w of the access on the memory port for one clock.
  void request(const Access& a, uint32_t w) {
    uint32_t mask = 0;
    uint64_t data = 0;
    if (a.kind == Access::Kind::kWrite) {
      for (uint32_t i = 0; i < kWordCells; ++i) {
        mask |= uint32_t{a.mask[w + i]} << i;
        data |= uint64_t{a.data[w + i]} << (8 * i);
      }
    }
    mem_req_valid_o.write(true);
    mem_req_write_o.write(a.kind == Access::Kind::kWrite);
    mem_req_bank_o.write(a.bank);
    mem_req_addr_o.write(a.segment * cells_ + w);
    mem_req_mask_o.write(mask);
    mem_req_data_o.write(data);
  }

  void run() {
    Unit unit;
    SmallFifo<Out, 2> out;
    Access access;                // the cycle's access, its words going out
    uint32_t next_word = cells_;  // its first cell not yet requested (cells_: none left)
    bool awaiting = false;        // a read's word is awaited on mem_resp
    std::vector<uint8_t> row;     // a read's cells so far
    // Not ready in reset: the edge that leaves reset is spent here.
    in_ready_o.write(false);
    cycle_ready_o.write(false);
    mem_req_valid_o.write(false);
    show(nullptr);
    write_stats(unit);
    wait();
    while (true) {
      const bool busy = awaiting || next_word < cells_;
      in_ready_o.write(!busy && unit.configured());
      cycle_ready_o.write(!busy && unit.configured() && out.size() <= 1);
      show(out.empty() ? nullptr : &out.front());
      write_stats(unit);
      wait();
      // Everything below sees the values from before this edge.
      mem_req_valid_o.write(false);
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      if (awaiting && mem_resp_valid_i.read()) {
        const auto data = mem_resp_data_i.read();
        for (uint32_t i = 0; i < kWordCells; ++i) {
          row.push_back(static_cast<uint8_t>(data.range(8 * i + 7, 8 * i).to_uint()));
        }
        if (row.size() == cells_) unit.map().capture(row);
        awaiting = false;
      }
      try {
        unit.configure(config());
      } catch (const std::invalid_argument&) {
        // Not a configuration yet (the ports before the driver writes them): no map.
      }
      if (in_valid_i.read() && in_ready_o.read()) {
        unit.receive(texram::video::video_item(static_cast<uint8_t>(in_flags_i.read()),
                                               static_cast<uint32_t>(in_texel_i.read())));
      }
      if (cycle_valid_i.read() && cycle_ready_o.read()) {
        Out o;
        o.granted = unit.cycle(cycle_sampler_i.read() != 0);
        const Access& a = unit.map().row_buffers().last_access();
        o.swap = unit.map().swapped();
        o.front = unit.map().front_buffer() != 0;
        if (a.kind != Access::Kind::kNone) {
          o.write = a.kind == Access::Kind::kWrite;
          o.read = a.kind == Access::Kind::kRead;
          o.fault = a.fault;
          o.wait = static_cast<uint32_t>(std::min<uint64_t>(a.wait, 0xFFFF));
          access = a;
          next_word = 0;
          row.clear();
        }
        out.push(o);
      }
      if (!awaiting && next_word < cells_) {
        request(access, next_word);
        next_word += kWordCells;
        awaiting = access.kind == Access::Kind::kRead;
      }
    }
  }
};

}  // namespace tmu::hls
