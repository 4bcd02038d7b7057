// SystemC model of the cube environment map's addressing unit (000 §7), the same ports and
// handshake as rtl/deflect/tmu_cube_address.sv. Its arithmetic is the golden
// deflect::cube_address (golden/deflect/cube_map.hpp: the major axis, the face coordinates,
// the normal encoder's divider, the texel coordinate); the module adds the clocking: one
// clocked thread, a registered ready and a two-entry output FIFO, so it sustains one vector
// per clock like the RTL (with a latency of one cycle instead of the RTL's seven).
//
// The face's log2 size L is an input field of every request, as on the RTL's port; the
// dividers' seed-table width is a constructor argument, as the RTL's parameter.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <systemc>

#include "deflect/cube_map.hpp"
#include "formats/formats.hpp"
#include "hls/common/small_fifo.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class CubeAddressSc : public sc_core::sc_module {
 public:
  template <int W>
  using uint_t = sc_dt::sc_uint<W>;
  template <int W>
  using int_t = sc_dt::sc_int<W>;
  static constexpr int kCompW = fmts::kUnitComp.width();
  static constexpr int kLog2W = fmts::kMipLog2.width();
  static constexpr int kFaceW = fmts::kCubeFace.width();
  static constexpr int kCoordW = fmts::kTexCoord.width();

  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};

  sc_core::sc_in<bool> in_valid_i{"in_valid_i"};
  sc_core::sc_out<bool> in_ready_o{"in_ready_o"};
  sc_core::sc_in<int_t<kCompW>> in_x_i{"in_x_i"};
  sc_core::sc_in<int_t<kCompW>> in_y_i{"in_y_i"};
  sc_core::sc_in<int_t<kCompW>> in_z_i{"in_z_i"};
  sc_core::sc_in<uint_t<kLog2W>> in_face_log2_i{"in_face_log2_i"};

  sc_core::sc_out<bool> out_valid_o{"out_valid_o"};
  sc_core::sc_in<bool> out_ready_i{"out_ready_i"};
  sc_core::sc_out<uint_t<kFaceW>> out_face_o{"out_face_o"};
  sc_core::sc_out<int_t<kCoordW>> out_u_o{"out_u_o"};
  sc_core::sc_out<int_t<kCoordW>> out_v_o{"out_v_o"};

  SC_HAS_PROCESS(CubeAddressSc);
  explicit CubeAddressSc(sc_core::sc_module_name name, int seed_bits = 7)
      : sc_core::sc_module(name), seed_bits_(seed_bits) {
    if (seed_bits < 2 || seed_bits > 12)
      throw std::invalid_argument("CubeAddressSc: seed bits 2..12");
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    SmallFifo<deflect::CubeAddress, 2> out;
    // Not ready in reset: a ready port promises the next edge will take the input, and the
    // edge that leaves reset is spent here.
    in_ready_o.write(false);
    out_valid_o.write(false);
    out_face_o.write(0);
    out_u_o.write(0);
    out_v_o.write(0);
    wait();
    while (true) {
      in_ready_o.write(out.size() <= 1);  // room for one more whatever the output does
      out_valid_o.write(!out.empty());
      out_face_o.write(out.empty() ? 0u : out.front().face);
      out_u_o.write(out.empty() ? 0 : out.front().u);
      out_v_o.write(out.empty() ? 0 : out.front().v);
      wait();
      // Everything below sees the values from before this edge.
      if (out_valid_o.read() && out_ready_i.read()) out.pop();
      if (in_ready_o.read() && in_valid_i.read()) {
        out.push(deflect::cube_address(
            in_x_i.read().to_int(), in_y_i.read().to_int(), in_z_i.read().to_int(),
            static_cast<int>(in_face_log2_i.read().to_uint()), seed_bits_));
      }
    }
  }

  int seed_bits_;
};

}  // namespace tmu::hls
