// SystemC model of the low-cost CCC texture unit (000 §4, Figs. 6 and 7), the same ports
// and handshakes as rtl/ccc/tmu_ccc_cache_bilinear.sv. Its arithmetic and cache policy are
// the golden model's (golden/ccc/ccc_cache_bilinear.hpp: footprint and the steps of
// BilinearCache, which CacheBilinearUnit::sample runs back to back); the module adds the
// clocking: one clocked thread that accepts a CLUT write or a request while idle, fetches the
// missing blocks through the one-outstanding memory port (request, response, CLUT colour a,
// CLUT colour b: the 2:1 multiplexer of Fig. 6), loads the blend into a one-entry output
// register, then runs the lookahead before it is idle again.
//
// The statistics count at the decision, as the RTL does: hits and misses when the request is
// looked up, prefetches when the blend is loaded.
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_ports.hpp"
#include "ccc/ccc_cache_bilinear.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

SC_MODULE(CccCacheBilinearSc) {
  TMU_SC_PORTS(ccc_cache_bilinear)

  SC_CTOR(CccCacheBilinearSc) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    // Reset. Not ready: a ready port promises the next edge takes the input, and the edge
    // that leaves reset is spent here.
    clut_ready_o.write(false);
    req_ready_o.write(false);
    mem_req_valid_o.write(false);
    mem_req_addr_o.write(0);
    out_valid_o.write(false);
    out_rgb_o.write(0);
    cache_.reset();
    out_full_ = false;
    out_rgb_ = 0;
    write_stats();
    wait();
    while (true) {
      // Idle: a CLUT write or a request (or both: the write is then ordered first).
      clut_ready_o.write(true);
      req_ready_o.write(true);
      step();
      clut_ready_o.write(false);
      req_ready_o.write(false);
      if (clut_valid_i.read()) {
        cache_.write_clut(static_cast<uint8_t>(clut_addr_i.read()),
                          static_cast<uint32_t>(clut_rgb_i.read()));
      }
      if (req_valid_i.read()) {
        serve(static_cast<int32_t>(signed_value(req_u_i.read(), fmts::kTexCoord)),
              static_cast<int32_t>(signed_value(req_v_i.read(), fmts::kTexCoord)));
      }
    }
  }

  // One clock: present the output register and the statistics, wait for the edge, and
  // retire the output if it was taken. Reads after it see the inputs from before the edge.
  void step() {
    out_valid_o.write(out_full_);
    out_rgb_o.write(out_rgb_);
    write_stats();
    wait();
    if (out_full_ && out_ready_i.read()) out_full_ = false;
  }

  // The ports keep the counts' low 32 bits: the RTL's registers wrap.
  void write_stats() {
    stat_hits_o.write(cache_.stats().hits);
    stat_misses_o.write(cache_.stats().misses);
    stat_prefetches_o.write(cache_.stats().prefetches);
  }

  uint32_t width() const { return static_cast<uint32_t>(cfg_width_i.read()); }
  uint32_t height() const { return static_cast<uint32_t>(cfg_height_i.read()); }

  // Fetches a block and decodes its colours into its entry.
  void fill(ccc::BlockXY b) {
    const uint32_t address = ccc::block_address(b, width());
    mem_req_addr_o.write(address);
    mem_req_valid_o.write(true);
    do {
      step();
    } while (!mem_req_ready_i.read());
    mem_req_valid_o.write(false);
    do {
      step();
    } while (!mem_resp_valid_i.read());
    const auto word = static_cast<uint32_t>(mem_resp_block_i.read());
    step();  // CLUT read of colour a
    step();  // CLUT read of colour b
    cache_.fill(b, address, word);
  }

  void fill(const ccc::BlockList& blocks) {
    for (uint32_t i = 0; i < blocks.count; ++i) fill(blocks.at[i]);
  }

  void serve(int32_t u_raw, int32_t v_raw) {
    const ccc::Footprint fp = ccc::footprint(u_raw, v_raw, width(), height());
    fill(cache_.look_up(fp, width()));
    const uint32_t rgb = cache_.blend(fp);
    while (out_full_) step();
    out_full_ = true;
    out_rgb_ = rgb;
    if (cfg_lookahead_i.read()) fill(cache_.look_ahead(u_raw, v_raw, width(), height()));
  }

  ccc::BilinearCache cache_;  // its CLUT is a RAM: reset keeps it
  bool out_full_ = false;
  uint32_t out_rgb_ = 0;
};

}  // namespace tmu::hls
