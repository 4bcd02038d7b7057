// SystemC model of the TEXRAM video path's page-row buffers and write arbiter (000 §11-12),
// the same ports and handshakes as rtl/texram/tmu_video_rows.sv. Its buffers, arbitration and
// pages are the golden cycle model's (texram::video::RowBuffers at 8-cell rows, 8 buffers a
// bank); the module adds the clocking: one clocked thread that takes a put, flush, hold or
// read item in one clock, and a cycle item (one memory cycle) when its two-entry output FIFO
// has room, with a registered ready. cfg_* (L and the read bound) are read at every clock.
#pragma once

#include <algorithm>
#include <cstdint>
#include <systemc>

#include "blocks/video_rows/video_rows_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"
#include "texram/video/row_buffers.hpp"

namespace tmu::hls {

class VideoRowsSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(video_rows)

  SC_HAS_PROCESS(VideoRowsSc);
  explicit VideoRowsSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  static constexpr uint32_t kCells = 8;

  struct Out {
    bool granted = false, write = false, read = false, fault = false, drained = false;
    unsigned bank = 0;
    uint32_t addr = 0;
    uint32_t mask = 0;
    uint64_t data = 0;
    uint32_t wait = 0;
  };

  void show(const Out* o) {
    out_valid_o.write(o != nullptr);
    out_granted_o.write(o && o->granted);
    out_write_o.write(o && o->write);
    out_read_o.write(o && o->read);
    out_fault_o.write(o && o->fault);
    out_bank_o.write(o ? o->bank : 0u);
    out_addr_o.write(o ? o->addr : 0u);
    out_mask_o.write(o ? o->mask : 0u);
    out_data_o.write(o ? o->data : 0u);
    out_wait_o.write(o ? o->wait : 0u);
    out_drained_o.write(o && o->drained);
  }

  // The ports keep the counts' low 32 bits: the RTL's registers wrap.
  void write_stats(const texram::video::ArbiterStats& s) {
    stat_cells_in_o.write(s.cells_in);
    stat_lost_writes_o.write(s.lost_writes);
    stat_forced_o.write(s.forced_writes);
    stat_max_ready_o.write(s.max_ready);
    stat_max_busy_bank_o.write(s.max_busy_bank);
  }

  static Out output(bool granted, const texram::video::RowBuffers& rows) {
    using Kind = texram::video::RowBuffers::Access::Kind;
    const texram::video::RowBuffers::Access& a = rows.last_access();
    Out o;
    o.granted = granted;
    o.drained = rows.held_frame_written();
    if (a.kind == Kind::kNone) return o;
    o.write = a.kind == Kind::kWrite;
    o.read = a.kind == Kind::kRead;
    o.fault = a.fault;
    o.bank = a.bank;
    o.addr = a.segment * kCells;
    for (size_t i = 0; i < a.mask.size(); ++i) {
      o.mask |= uint32_t{a.mask[i]} << i;
      o.data |= uint64_t{a.data[i]} << (8 * i);
    }
    o.wait = static_cast<uint32_t>(std::min<uint64_t>(a.wait, 0xFFFF));
    return o;
  }

  void run() {
    texram::BankImage memory;
    for (auto& bank : memory) bank.assign(size_t{1} << formats::kBankAddr.width(), 0);
    texram::video::ArbiterConfig config;
    config.segment_cells = kCells;
    config.buffers_per_bank = 8;
    texram::video::RowBuffers rows(config, memory);
    SmallFifo<Out, 2> out;
    // Not ready in reset: the edge that leaves reset is spent here.
    put_ready_o.write(false);
    flush_ready_o.write(false);
    hold_ready_o.write(false);
    read_ready_o.write(false);
    cycle_ready_o.write(false);
    show(nullptr);
    write_stats(rows.stats());
    wait();
    while (true) {
      put_ready_o.write(true);
      flush_ready_o.write(true);
      hold_ready_o.write(true);
      read_ready_o.write(true);
      cycle_ready_o.write(out.size() <= 1);
      show(out.empty() ? nullptr : &out.front());
      write_stats(rows.stats());
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      rows.set_waits(static_cast<uint32_t>(cfg_max_wait_i.read()),
                     static_cast<uint32_t>(cfg_read_wait_i.read()));
      if (put_valid_i.read() && put_ready_o.read()) {
        rows.put(static_cast<unsigned>(put_bank_i.read()), static_cast<uint32_t>(put_addr_i.read()),
                 static_cast<uint8_t>(put_value_i.read()), static_cast<uint32_t>(put_tag_i.read()));
      }
      if (flush_valid_i.read() && flush_ready_o.read()) {
        rows.flush(static_cast<uint32_t>(flush_tag_i.read()));
      }
      if (hold_valid_i.read() && hold_ready_o.read()) {
        rows.hold_after(static_cast<uint32_t>(hold_tag_i.read()));
      }
      if (read_valid_i.read() && read_ready_o.read()) {
        rows.request_read(static_cast<unsigned>(read_bank_i.read()),
                          static_cast<uint32_t>(read_addr_i.read()) / kCells);
      }
      if (cycle_valid_i.read() && cycle_ready_o.read()) {
        const bool granted = rows.cycle(cycle_sampler_i.read() != 0);
        out.push(output(granted, rows));
      }
    }
  }
};

}  // namespace tmu::hls
