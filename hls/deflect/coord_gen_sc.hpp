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

#include "deflect/coord_table_memory.hpp"
#include "formats/formats.hpp"
#include "hls/common/small_fifo.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class CoordGenSc : public sc_core::sc_module {
 public:
  template <int W>
  using uint_t = sc_dt::sc_uint<W>;
  template <int W>
  using int_t = sc_dt::sc_int<W>;

  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};

  sc_core::sc_in<bool> tw_valid_i{"tw_valid_i"};
  sc_core::sc_out<bool> tw_ready_o{"tw_ready_o"};
  sc_core::sc_in<uint_t<fmts::kCoordTableId.width()>> tw_table_i{"tw_table_i"};
  sc_core::sc_in<uint_t<fmts::kCoordTableAddr.width()>> tw_addr_i{"tw_addr_i"};
  sc_core::sc_in<int_t<fmts::kCoordValue.width()>> tw_value_i{"tw_value_i"};

  sc_core::sc_in<bool> in_valid_i{"in_valid_i"};
  sc_core::sc_out<bool> in_ready_o{"in_ready_o"};
  sc_core::sc_in<uint_t<fmts::kSpherePhi.width()>> in_phi_i{"in_phi_i"};
  sc_core::sc_in<uint_t<fmts::kSphereTheta.width()>> in_theta_i{"in_theta_i"};

  sc_core::sc_out<bool> out_valid_o{"out_valid_o"};
  sc_core::sc_in<bool> out_ready_i{"out_ready_i"};
  sc_core::sc_out<int_t<fmts::kUnitComp.width()>> out_un_o{"out_un_o"};
  sc_core::sc_out<int_t<fmts::kUnitComp.width()>> out_vn_o{"out_vn_o"};
  sc_core::sc_out<int_t<fmts::kUnitComp.width()>> out_ur_o{"out_ur_o"};
  sc_core::sc_out<int_t<fmts::kUnitComp.width()>> out_vr_o{"out_vr_o"};
  sc_core::sc_out<int_t<fmts::kUnitComp.width()>> out_wr_o{"out_wr_o"};

  SC_HAS_PROCESS(CoordGenSc);
  explicit CoordGenSc(sc_core::sc_module_name name, const deflect::TableConfig& config = {})
      : sc_core::sc_module(name), tables_(config) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void write_out(const deflect::MapCoords& c) {
    out_un_o.write(c.un);
    out_vn_o.write(c.vn);
    out_ur_o.write(c.ur);
    out_vr_o.write(c.vr);
    out_wr_o.write(c.wr);
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
                       static_cast<int32_t>(tw_value_i.read().to_int())});
      }
    }
  }

  deflect::CoordTableMemory tables_;
};

}  // namespace tmu::hls
