// SystemC model of the bump deflection unit with its MBR (001 §4.4, Fig. 5; §6.2), the same
// ports and handshakes as rtl/deflect/tmu_deflect.sv at the default grid (A = 9). The
// arithmetic and the MBR's hit/miss decisions are the golden model's (golden/deflect/
// bump_map.hpp's unpack_bump, s2s_map.hpp's deflect_address and MapBuffer: the steps
// DeflectionUnit::deflect runs); the
// module adds the clocking, and fills its MapBuffer from the map memory port, so the entries
// it reads are the ones the memory sent.
//
// One clocked thread. Requests wait in a two-entry input FIFO (a registered ready that keeps
// one request per clock) and are looked up one at a time, in order, at the FIFO's head: a
// bypass (k = Q) or a tag hit goes to the two-entry output FIFO at once; a miss sends the
// block request for one cycle and holds the head until the response, which fills the MBR
// and then serves the head as a miss. So the MBR is read and written in request order, the
// golden model's sequential semantics, and a miss costs the memory's latency.
#pragma once

#include <array>
#include <cstdint>
#include <systemc>

#include "blocks/deflect/deflect_ports.hpp"
#include "deflect/bump_map.hpp"
#include "deflect/s2s_map.hpp"
#include "deflect/sphere_grid.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

SC_MODULE(DeflectSc) {
  TMU_SC_PORTS(deflect)

  SC_CTOR(DeflectSc) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  struct Request {
    deflect::SphereAngle normal, bump;
  };

  static constexpr int kEntryW = fmts::kS2sEntry.width();
  static_assert(kEntryW == 2 * fmts::kSpherePhi.width() - 3,
                "an entry is l_phi (A - 1 bits) and l_theta (A - 2)");

  void run() {
    // Reset. Not ready: a ready port promises the next edge takes the input, and the edge
    // that leaves reset is spent here.
    in_ready_o.write(false);
    out_valid_o.write(false);
    out_phi_o.write(0);
    out_theta_o.write(0);
    out_access_o.write(0);
    map_req_valid_o.write(false);
    map_req_block_o.write(0);
    in_.clear();
    out_.clear();
    mbr_.reset();
    fetching_ = missed_ = false;
    wait();
    while (true) {
      in_ready_o.write(!in_.full());
      out_valid_o.write(!out_.empty());
      if (!out_.empty()) {
        out_phi_o.write(out_.front().normal.phi);
        out_theta_o.write(out_.front().normal.theta);
        out_access_o.write(static_cast<uint32_t>(out_.front().access));
      }
      wait();
      // Everything below sees the values from before this edge.
      map_req_valid_o.write(false);
      if (out_valid_o.read() && out_ready_i.read()) out_.pop();
      if (in_ready_o.read() && in_valid_i.read()) {
        in_.push({{static_cast<uint32_t>(in_normal_phi_i.read()),
                   static_cast<uint32_t>(in_normal_theta_i.read())},
                  deflect::unpack_bump(grid_,
                                       unpack_rgb(static_cast<uint32_t>(in_bump_texel_i.read())))});
      }
      if (map_resp_valid_i.read()) fill();
      if (!in_.empty() && !fetching_ && !out_.full()) look_up();
    }
  }

  // The block arrives: it becomes the MBR's content with the tag that was asked for.
  void fill() {
    const auto data = map_resp_data_i.read();
    std::array<uint32_t, fmts::kS2sBlockEntries> block{};
    for (int o = 0; o < fmts::kS2sBlockEntries; ++o) {
      block[static_cast<size_t>(o)] =
          static_cast<uint32_t>(data.range(kEntryW * o + kEntryW - 1, kEntryW * o).to_uint());
    }
    mbr_.fill(fetch_block_, block);
    fetching_ = false;
  }

  // The head of the input FIFO: served when its entry is known, else its block is requested.
  void look_up() {
    const Request& r = in_.front();
    const deflect::MapAddress a = deflect::deflect_address(grid_, r.normal, r.bump);
    const deflect::MapAccess access = mbr_.access(a);
    if (access == deflect::MapAccess::kMiss) {
      map_req_valid_o.write(true);
      map_req_block_o.write(a.block);
      fetching_ = missed_ = true;
      fetch_block_ = a.block;
      return;
    }
    // A head served after its fill hits the MBR, but it missed.
    out_.push({mbr_.deflected(r.normal, a), missed_ ? deflect::MapAccess::kMiss : access});
    in_.pop();
    missed_ = false;
  }

  const deflect::SphereGrid grid_{fmts::kSpherePhi.width()};
  SmallFifo<Request, 2> in_;
  SmallFifo<deflect::Deflected, 2> out_;
  deflect::MapBuffer mbr_{grid_};
  bool fetching_ = false;  // a block request is outstanding
  bool missed_ = false;    // the head's look-up missed: it reports a miss when served
  uint32_t fetch_block_ = 0;
};

}  // namespace tmu::hls
