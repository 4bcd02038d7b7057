// SystemC model of the low-cost CCC texture unit (000 §4, Figs. 6 and 7), the same ports
// and handshakes as rtl/ccc/tmu_ccc_cache_bilinear.sv. Its arithmetic is the golden model's
// (golden/ccc/ccc_cache_bilinear.hpp: footprint, footprint_blocks, lookahead_blocks,
// cache_slot, block_address, entry_texel, bilerp_rgb); the module adds the clocking: one
// clocked thread that accepts a CLUT write or a request while idle, fetches the missing
// blocks through the one-outstanding memory port (request, response, CLUT colour a, CLUT
// colour b: the 2:1 multiplexer of Fig. 6), loads the blend into a one-entry output
// register, then runs the lookahead before it is idle again.
//
// The statistics count at the decision, as the RTL does: hits and misses when the request is
// looked up, prefetches when the blend is loaded; the blocks of one step (a footprint, or a
// lookahead) sit in different entries, so deciding them all before fetching any is the
// golden model's block-by-block order.
#pragma once

#include <array>
#include <cstdint>
#include <systemc>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_ports.hpp"
#include "ccc/ccc_cache_bilinear.hpp"
#include "ccc/ccc_texture.hpp"
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
    entries_ = {};
    out_full_ = false;
    out_rgb_ = 0;
    hits_ = misses_ = prefetches_ = 0;
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
        clut_[static_cast<uint8_t>(clut_addr_i.read())] = static_cast<uint32_t>(clut_rgb_i.read());
        for (ccc::CacheEntry& e : entries_) e.valid = false;  // the decoded colours are stale
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

  void write_stats() {
    stat_hits_o.write(hits_);
    stat_misses_o.write(misses_);
    stat_prefetches_o.write(prefetches_);
  }

  uint32_t width() const { return static_cast<uint32_t>(cfg_width_i.read()); }
  uint32_t height() const { return static_cast<uint32_t>(cfg_height_i.read()); }

  bool present(ccc::BlockXY b) const {
    const ccc::CacheEntry& e = entries_[ccc::cache_slot(b)];
    return e.valid && e.tag == ccc::block_address(b, width());
  }

  // The blocks of `list` that are not present, in list order.
  ccc::BlockList missing(const ccc::BlockList& list) const {
    ccc::BlockList out;
    for (uint32_t i = 0; i < list.count; ++i) {
      if (!present(list.at[i])) out.at[out.count++] = list.at[i];
    }
    return out;
  }

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
    const ccc::Block blk = ccc::Block::from_word(static_cast<uint32_t>(mem_resp_block_i.read()));
    step();  // CLUT read of colour a
    step();  // CLUT read of colour b
    entries_[ccc::cache_slot(b)] = {true, address, clut_[blk.a], clut_[blk.b], blk.bits};
  }

  void serve(int32_t u_raw, int32_t v_raw) {
    const ccc::Footprint fp = ccc::footprint(u_raw, v_raw, width(), height());
    const ccc::BlockList need = ccc::footprint_blocks(fp);
    const ccc::BlockList miss = missing(need);
    hits_ += need.count - miss.count;
    misses_ += miss.count;
    for (uint32_t i = 0; i < miss.count; ++i) fill(miss.at[i]);

    auto texel = [&](uint32_t x, uint32_t y) {
      return ccc::entry_texel(entries_[ccc::cache_slot({x / 4, y / 4})], x, y);
    };
    const uint32_t rgb = ccc::bilerp_rgb(texel(fp.x0, fp.y0), texel(fp.x1, fp.y0),
                                         texel(fp.x0, fp.y1), texel(fp.x1, fp.y1), fp.fx, fp.fy);
    while (out_full_) step();
    out_full_ = true;
    out_rgb_ = rgb;

    if (!cfg_lookahead_i.read()) return;
    const ccc::BlockList ahead = missing(ccc::lookahead_blocks(u_raw, v_raw, width(), height()));
    prefetches_ += ahead.count;
    for (uint32_t i = 0; i < ahead.count; ++i) fill(ahead.at[i]);
  }

  std::array<uint32_t, fmts::kClutEntries> clut_{};  // a RAM: no reset
  std::array<ccc::CacheEntry, fmts::kCccCacheEntries> entries_{};
  bool out_full_ = false;
  uint32_t out_rgb_ = 0;
  uint32_t hits_ = 0, misses_ = 0, prefetches_ = 0;  // 32-bit registers: wrap like the RTL
};

}  // namespace tmu::hls
