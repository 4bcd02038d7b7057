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

#include "blocks/cube_address/cube_address_ports.hpp"
#include "deflect/cube_map.hpp"
#include "formats/formats.hpp"
#include "hls/common/one_per_clock.hpp"
#include "hls/common/sc_ports.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class CubeAddressSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(cube_address)

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
    run_one_per_clock<deflect::CubeAddress>(
        *this,
        [this](const deflect::CubeAddress* a) {
          out_face_o.write(a ? a->face : 0u);
          out_u_o.write(a ? coord_bits(a->u) : 0u);
          out_v_o.write(a ? coord_bits(a->v) : 0u);
        },
        [this] {
          const fx::Format c = fmts::kUnitComp;
          return deflect::cube_address(static_cast<int32_t>(signed_value(in_x_i.read(), c)),
                                       static_cast<int32_t>(signed_value(in_y_i.read(), c)),
                                       static_cast<int32_t>(signed_value(in_z_i.read(), c)),
                                       static_cast<int>(in_face_log2_i.read().to_uint()),
                                       seed_bits_);
        });
  }

  // A TexCoord's port bits: its two's complement pattern.
  static uint64_t coord_bits(int32_t v) {
    return static_cast<uint64_t>(int64_t{v}) & ((uint64_t{1} << fmts::kTexCoord.width()) - 1);
  }

  int seed_bits_;
};

}  // namespace tmu::hls
