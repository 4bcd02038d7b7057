// SystemC model of the normal encoder (001 §4.1, eq. 12-16, Fig. 3), the same ports and
// handshake as rtl/deflect/tmu_normal_encoder.sv at the default grid (A = 9). Its arithmetic
// is the golden deflect::NormalEncoder (golden/deflect/normal_encoder.hpp: the dividers, the
// angle table, the octant expansion); the module adds the clocking: one clocked thread, a
// registered ready and a two-entry output FIFO, so it sustains one normal per clock like the
// RTL (with a latency of one cycle instead of the RTL's eight).
//
// The encoder's configuration (seed and angle-table widths) is a constructor argument, as
// the RTL's parameters; its grid must be the ports' (A = 9).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <systemc>

#include "blocks/normal_encoder/normal_encoder_ports.hpp"
#include "deflect/normal_encoder.hpp"
#include "formats/formats.hpp"
#include "hls/common/one_per_clock.hpp"
#include "hls/common/sc_ports.hpp"

namespace tmu::hls {

namespace fmts = tmu::formats;

class NormalEncoderSc : public sc_core::sc_module {
 public:
  TMU_SC_PORTS(normal_encoder)

  SC_HAS_PROCESS(NormalEncoderSc);
  NormalEncoderSc(sc_core::sc_module_name name, const deflect::EncoderConfig& config = {})
      : sc_core::sc_module(name), encoder_(config) {
    if (config.grid.phi_bits != fmts::kSpherePhi.width())
      throw std::invalid_argument("NormalEncoderSc: the ports are built for the A = 9 grid");
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    run_one_per_clock<deflect::SphereAngle>(
        *this,
        [this](const deflect::SphereAngle* a) {
          out_phi_o.write(a ? a->phi : 0u);
          out_theta_o.write(a ? a->theta : 0u);
        },
        [this] {
          const fx::Format c = fmts::kUnitComp;
          return encoder_.encode(static_cast<int16_t>(signed_value(in_x_i.read(), c)),
                                 static_cast<int16_t>(signed_value(in_y_i.read(), c)),
                                 static_cast<int16_t>(signed_value(in_z_i.read(), c)));
        });
  }

  deflect::NormalEncoder encoder_;
};

}  // namespace tmu::hls
