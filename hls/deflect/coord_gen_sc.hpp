// SystemC model of the shading- and environment-map coordinate generator (001 §5,
// eq. 17-22), the same ports and handshake as rtl/deflect/tmu_coord_gen.sv. Its tables are a
// deflect::CoordTableMemory loaded through the write port (golden/deflect/coord_table_memory.hpp:
// writes beyond a table change nothing, -2^(W-1) is stored as -(2^(W-1) - 1)) and its
// arithmetic is the golden eval_coords(). One clocked thread, a registered ready and a
// two-entry output FIFO: one normal per clock, like the RTL (not its latency).
//
// Ordering, as the RTL: a request is evaluated on the tables as they are at the edge that
// accepts it, before a write accepted at the same edge; the write port is always ready.
// The grid and the table width (deflect::TableConfig) are a constructor argument, as the RTL's
// parameters; the ports have the package widths and a smaller grid or width uses their low
// bits.
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/coord_gen/coord_gen_ports.hpp"
#include "deflect/coord_table_memory.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/common/small_fifo.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class CoordGenSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(coord_gen)

  SC_HAS_PROCESS(CoordGenSc);
  explicit CoordGenSc(sc_core::sc_module_name name, const deflect::TableConfig& config = {})
      : sc_core::sc_module(name), tables_(config) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  // A component's two's complement bits on its port.
  static uint64_t raw(int32_t v) {
    return static_cast<uint64_t>(v) & ((uint64_t{1} << fmts::kUnitComp.width()) - 1);
  }
  void write_out(const deflect::MapCoords& c) {
    out_un_o.write(raw(c.un));
    out_vn_o.write(raw(c.vn));
    out_ur_o.write(raw(c.ur));
    out_vr_o.write(raw(c.vr));
    out_wr_o.write(raw(c.wr));
  }

  void run() {
    SmallFifo<deflect::MapCoords, 2> out;
    // Not ready in reset: a ready port promises the next edge will take the input, and the
    // edge that leaves reset is spent here.
    tw_ready_o.write(false);
    in_ready_o.write(false);
    out_valid_o.write(false);
    write_out({});
    wait();
    while (true) {
      tw_ready_o.write(true);
      in_ready_o.write(out.size() <= 1);  // room for one more whatever the output does
      out_valid_o.write(!out.empty());
      write_out(out.empty() ? deflect::MapCoords{} : out.front());
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      if (in_ready_o.read() && in_valid_i.read()) {
        const deflect::SphereAngle normal{static_cast<uint32_t>(in_phi_i.read()),
                                          static_cast<uint32_t>(in_theta_i.read())};
        out.push(tables_.eval(normal));
      }
      if (tw_ready_o.read() && tw_valid_i.read()) {
        tables_.write({static_cast<uint8_t>(tw_table_i.read()),
                       static_cast<uint32_t>(tw_addr_i.read()),
                       static_cast<int32_t>(signed_value(tw_value_i.read(), fmts::kCoordValue))});
      }
    }
  }

  deflect::CoordTableMemory tables_;
};

}  // namespace tmu::hls
