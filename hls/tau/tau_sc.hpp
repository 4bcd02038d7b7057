// SystemC model of the tau unit (004: EP0637814 claims 4-6, 15), the same ports and handshakes
// as rtl/tau/tmu_tau.sv. Its arithmetic is the golden tau::TauUnit (golden/tau/tau_unit.hpp:
// the node memory, the weights, the sums, r and lambda); the module adds the clocking: one
// clocked thread that, while idle, takes a node write or a sample (both in one cycle: the write
// first, as in the RTL), spends the RTL's cycles on a sample (N + 7: 4 or 16 node reads and
// seven steps around them), then loads a one-entry output register when it is free.
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/tau/tau_ports.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "tau/tau_unit.hpp"

namespace tmu::hls {

SC_MODULE(TauSc) {
  TMU_SC_PORTS(tau)

  SC_CTOR(TauSc) {
    SC_CTHREAD(run, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void run() {
    // Not ready in reset: a ready port promises the next edge takes the input, and the edge
    // that leaves reset is spent here.
    node_ready_o.write(false);
    in_ready_o.write(false);
    out_full_ = false;
    show();
    wait();
    while (true) {
      node_ready_o.write(true);
      in_ready_o.write(true);
      step();
      node_ready_o.write(false);
      in_ready_o.write(false);
      if (node_valid_i.read()) {
        unit_.write(static_cast<uint32_t>(node_addr_i.read()),
                    static_cast<int32_t>(signed_value(node_u_i.read(), formats::kTexCoord)),
                    static_cast<int32_t>(signed_value(node_v_i.read(), formats::kTexCoord)));
      }
      if (in_valid_i.read()) serve();
    }
  }

  // One clock: present the output register, wait for the edge, retire the output if taken.
  void step() {
    show();
    wait();
    if (out_full_ && out_ready_i.read()) out_full_ = false;
  }

  void show() {
    const auto bits = [](int32_t raw, const fx::Format& f) {
      return static_cast<uint64_t>(static_cast<uint32_t>(raw)) & ((uint64_t{1} << f.width()) - 1);
    };
    out_valid_o.write(out_full_);
    out_u_o.write(bits(out_.u, formats::kTexCoord));
    out_v_o.write(bits(out_.v, formats::kTexCoord));
    out_r1u_o.write(bits(out_.r1u, formats::kTexDeriv));
    out_r1v_o.write(bits(out_.r1v, formats::kTexDeriv));
    out_r2u_o.write(bits(out_.r2u, formats::kTexDeriv));
    out_r2v_o.write(bits(out_.r2v, formats::kTexDeriv));
    out_lambda_o.write(bits(out_.lambda, formats::kLod));
  }

  void serve() {
    tau::Config config;
    config.cells_s = static_cast<int>(cfg_cells_s_i.read());
    config.cells_t = static_cast<int>(cfg_cells_t_i.read());
    config.interp = cfg_interp_i.read() != 0 ? tau::Interp::kSpline : tau::Interp::kLinear;
    unit_.configure(config);
    const fx::Format pc = formats::kPcCoord, pd = formats::kPcDeriv;
    tau::Request r;
    r.s = static_cast<int32_t>(signed_value(in_s_i.read(), pc));
    r.t = static_cast<int32_t>(signed_value(in_t_i.read(), pc));
    r.ds_dx = static_cast<int32_t>(signed_value(in_ds_dx_i.read(), pd));
    r.dt_dx = static_cast<int32_t>(signed_value(in_dt_dx_i.read(), pd));
    r.ds_dy = static_cast<int32_t>(signed_value(in_ds_dy_i.read(), pd));
    r.dt_dy = static_cast<int32_t>(signed_value(in_dt_dy_i.read(), pd));
    const tau::Result result = unit_.sample(r);
    // The RTL's Weigh, Read x N, Drain, Round, Dx, Dy, Square; Log loads the output.
    const int reads = config.interp == tau::Interp::kSpline ? 16 : 4;
    for (int c = 0; c < reads + 6; ++c) step();
    while (out_full_) step();
    out_full_ = true;
    out_ = result;
  }

  tau::TauUnit unit_;  // its node memory is a RAM: reset keeps it
  bool out_full_ = false;
  tau::Result out_;
};

}  // namespace tmu::hls
