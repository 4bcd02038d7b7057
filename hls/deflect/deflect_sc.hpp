// SystemC model of the bump deflection unit with its MBR (001 §4.4, Fig. 5; §6.2), the same
// ports and handshakes as rtl/deflect/tmu_deflect.sv at the default grid (A = 9). Its
// arithmetic is the golden model's (golden/deflect/s2s_map.hpp: map_address, expand_phi,
// make_theta, and the z = 0 column of DeflectionUnit::deflect); the module adds the clocking
// and its own MBR, filled from the map memory port, so the entries it reads are the ones the
// memory sent.
//
// One clocked thread. Requests wait in a two-entry input FIFO (a registered ready that keeps
// one request per clock) and are looked up one at a time, in order, at the FIFO's head: a
// bypass (k = Q) or a tag hit goes to the two-entry output FIFO at once; a miss sends the
// block request for one cycle and holds the head until the response, which fills the MBR
// and then serves the head as a miss. So the MBR is read and written in request order, the
// golden model's sequential semantics, and a miss costs the memory's latency.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <systemc>

#include "blocks/deflect/deflect_ports.hpp"
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
  struct Result {
    uint32_t phi = 0, theta = 0;
    deflect::MapAccess access = deflect::MapAccess::kHit;
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
    mbr_valid_ = fetching_ = missed_ = false;
    wait();
    while (true) {
      in_ready_o.write(!in_.full());
      out_valid_o.write(!out_.empty());
      if (!out_.empty()) {
        out_phi_o.write(out_.front().phi);
        out_theta_o.write(out_.front().theta);
        out_access_o.write(static_cast<uint32_t>(out_.front().access));
      }
      wait();
      // Everything below sees the values from before this edge.
      map_req_valid_o.write(false);
      if (out_valid_o.read() && out_ready_i.read()) out_.pop();
      if (in_ready_o.read() && in_valid_i.read()) {
        in_.push({{static_cast<uint32_t>(in_normal_phi_i.read()),
                   static_cast<uint32_t>(in_normal_theta_i.read())},
                  {static_cast<uint32_t>(in_bump_phi_i.read()),
                   static_cast<uint32_t>(in_bump_theta_i.read())}});
      }
      if (map_resp_valid_i.read()) fill();
      if (!in_.empty() && !fetching_ && !out_.full()) look_up();
    }
  }

  // The block arrives: it becomes the MBR's content with the tag that was asked for.
  void fill() {
    const auto data = map_resp_data_i.read();
    for (int o = 0; o < fmts::kS2sBlockEntries; ++o) {
      mbr_[static_cast<size_t>(o)] =
          static_cast<uint32_t>(data.range(kEntryW * o + kEntryW - 1, kEntryW * o).to_uint());
    }
    mbr_valid_ = true;
    mbr_tag_ = fetch_block_;
    fetching_ = false;
  }

  // The head of the input FIFO: served when its entry is known, else its block is requested.
  void look_up() {
    const Request& r = in_.front();
    const uint32_t q = grid_.quarter();
    const uint32_t phi_prime = static_cast<uint32_t>(static_cast<int32_t>(r.bump.phi) -
                                                     deflect::theta_steps(grid_, r.normal.theta)) &
                               grid_.phi_mask();
    const deflect::MapAddress a = deflect::map_address(grid_, phi_prime, r.bump.theta);
    Result res;
    uint32_t l_phi = q, l_theta = std::min(q - a.k_theta, q - 1);  // z = 0: no look-up
    if (a.k == q) {
      res.access = deflect::MapAccess::kBypass;
    } else if (mbr_valid_ && mbr_tag_ == a.block) {
      res.access = missed_ ? deflect::MapAccess::kMiss : deflect::MapAccess::kHit;
      const uint32_t e = mbr_[a.offset];
      l_phi = e >> grid_.mag_bits();
      l_theta = e & (q - 1);
    } else {
      map_req_valid_o.write(true);
      map_req_block_o.write(a.block);
      fetching_ = missed_ = true;
      fetch_block_ = a.block;
      return;
    }
    res.phi = (deflect::expand_phi(grid_, a.sx, a.sz, l_phi) + r.normal.phi) & grid_.phi_mask();
    res.theta = deflect::make_theta(grid_, a.sy, l_theta);
    out_.push(res);
    in_.pop();
    missed_ = false;
  }

  const deflect::SphereGrid grid_{fmts::kSpherePhi.width()};
  SmallFifo<Request, 2> in_;
  SmallFifo<Result, 2> out_;
  std::array<uint32_t, fmts::kS2sBlockEntries> mbr_{};
  bool mbr_valid_ = false;
  uint32_t mbr_tag_ = 0;
  bool fetching_ = false;  // a block request is outstanding
  bool missed_ = false;    // the head's look-up missed: it reports a miss when served
  uint32_t fetch_block_ = 0;
};

}  // namespace tmu::hls
