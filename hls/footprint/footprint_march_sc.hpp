// What the SystemC models of the footprint unit share (footprint_sc.hpp on the trilinear unit,
// footprint_clip_sc.hpp on the clip-map): the marcher's side of a fragment and the averager,
// around a sampler model the derived module instantiates and wires to the probe and result
// signals here. The arithmetic is golden's (golden/footprint/footprint.hpp: plan for the
// setup, probe for each probe's position, average for the result).
//
// - issue(): a fragment's probe count k = log2 N is pushed into the count FIFO (waiting while
//   the averager is kCountDepth fragments behind), and its N probes are presented one per clock
//   to the sampler (each held until taken). stat_probes_o counts the probes taken (wraps).
// - collect(), a clocked thread: pops k, collects the sampler's next N results, averages them
//   and loads a one-entry ready/valid output register.
//
// Derived (CRTP) is the sc_module with the block's ports (TMU_SC_PORTS): the fragment (req_*),
// the setup's configuration (cfg_log2_max_probes_i, cfg_q_rule_i), the border modes
// (cfg_border_u_i, cfg_border_v_i), the output (out_*) and stat_probes_o. A
// cfg_log2_max_probes_i above formats::kMaxProbeLog2 acts as kMaxProbeLog2; bad setup widths
// throw std::invalid_argument at construction.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <systemc>

#include "footprint/footprint.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::hls {

template <class Derived>
class FootprintMarchSc : public sc_core::sc_module {
 public:
  // Fragments planned whose results the averager has not yet collected, at most.
  static constexpr int kCountDepth = 4;

 protected:
  FootprintMarchSc(sc_core::sc_module_name name, const footprint::Widths& widths)
      : sc_core::sc_module(name), widths_(widths) {
    // plan() checks the widths: fail at elaboration, not in the middle of a run.
    (void)footprint::plan(footprint::Request{},
                          footprint::Config{0, footprint::QRule::kHeights, widths_});
  }

  Derived& self() { return static_cast<Derived&>(*this); }

  // The marcher's reset: no probe, the counter at 0.
  void reset_probes() {
    probe_valid_.write(false);
    probe_u_.write(0);
    probe_v_.write(0);
    probe_lambda_.write(0);
    probe_shade_.write(0);
    probes_ = 0;
    self().stat_probes_o.write(0);
  }

  // The fragment on the request port, its setup configuration, and the border modes probe()
  // needs (a coordinate beyond the port wraps or saturates): read at the edge that takes it.
  footprint::Request fragment_request() {
    Derived& d = self();
    const auto coord = [](const auto& port) {
      return static_cast<int32_t>(signed_value(port.read(), formats::kTexCoord));
    };
    const auto deriv = [](const auto& port) {
      return static_cast<int32_t>(signed_value(port.read(), formats::kTexDeriv));
    };
    return {coord(d.req_u_i),
            coord(d.req_v_i),
            deriv(d.req_r1u_i),
            deriv(d.req_r1v_i),
            deriv(d.req_r2u_i),
            deriv(d.req_r2v_i),
            static_cast<uint32_t>(d.req_shade_i.read())};
  }
  footprint::Config footprint_config() {
    footprint::Config c;
    c.log2_max_probes = std::min(static_cast<int>(self().cfg_log2_max_probes_i.read().to_uint()),
                                 formats::kMaxProbeLog2);
    c.q_rule = static_cast<footprint::QRule>(self().cfg_q_rule_i.read().to_uint());
    c.widths = widths_;
    return c;
  }
  texram::SamplerConfig sampler_config() {
    texram::SamplerConfig c;
    c.border_u = static_cast<texram::Border>(self().cfg_border_u_i.read().to_uint());
    c.border_v = static_cast<texram::Border>(self().cfg_border_v_i.read().to_uint());
    return c;
  }

  // The fragment's probes to the sampler, one per clock while it takes them.
  void issue(const footprint::Request& request, const footprint::Plan& plan,
             const texram::SamplerConfig& sampler) {
    while (!counts_.nb_write(plan.log2_n)) sc_core::wait();  // the averager is behind
    const int n = 1 << plan.log2_n;
    for (int i = 0; i < n; ++i) {
      const texram::Request q = footprint::probe(request, plan, i, sampler);
      // Raw port bits (the sampler's ports are its description's).
      probe_u_.write(static_cast<uint32_t>(q.u) & ((1u << formats::kTexCoord.width()) - 1));
      probe_v_.write(static_cast<uint32_t>(q.v) & ((1u << formats::kTexCoord.width()) - 1));
      probe_lambda_.write(static_cast<uint32_t>(q.lambda) & ((1u << formats::kLod.width()) - 1));
      probe_shade_.write(q.shade);
      probe_valid_.write(true);
      do {
        sc_core::wait();
      } while (!probe_ready_.read());
      ++probes_;
      self().stat_probes_o.write(probes_);
    }
    probe_valid_.write(false);
  }

  void collect() {
    Derived& d = self();
    d.out_valid_o.write(false);
    d.out_rgba_o.write(0);
    result_ready_.write(false);
    out_full_ = false;
    out_rgba_ = 0;
    for (int stale = 0; counts_.nb_read(stale);) {
    }
    sc_core::wait();
    while (true) {
      int log2_n = 0;
      while (!counts_.nb_read(log2_n)) step();
      const int n = 1 << log2_n;
      std::array<uint32_t, size_t{1} << formats::kMaxProbeLog2> colours{};
      result_ready_.write(true);
      for (int i = 0; i < n;) {
        step();
        if (result_valid_.read()) {
          colours[static_cast<size_t>(i++)] = static_cast<uint32_t>(result_rgba_.read());
        }
      }
      result_ready_.write(false);
      const uint32_t rgba =
          footprint::average(std::span(colours.data(), static_cast<size_t>(n)), log2_n);
      while (out_full_) step();
      out_full_ = true;
      out_rgba_ = rgba;
    }
  }

  template <int W>
  using sig = sc_core::sc_signal<sc_port_t<W>>;

  // The sampler's request and result ports, wired by the derived module.
  sc_core::sc_signal<bool> probe_valid_{"probe_valid"}, probe_ready_{"probe_ready"};
  sig<formats::kTexCoord.width()> probe_u_{"probe_u"}, probe_v_{"probe_v"};
  sig<formats::kLod.width()> probe_lambda_{"probe_lambda"};
  sig<formats::kRgba8888.width()> probe_shade_{"probe_shade"};
  sc_core::sc_signal<bool> result_valid_{"result_valid"}, result_ready_{"result_ready"};
  sig<formats::kRgba8888.width()> result_rgba_{"result_rgba"};

 private:
  // One clock of the averager: present the output register, wait for the edge, and retire the
  // output if it was taken. Reads after it see the inputs from before the edge.
  void step() {
    Derived& d = self();
    d.out_valid_o.write(out_full_);
    d.out_rgba_o.write(out_rgba_);
    sc_core::wait();
    if (out_full_ && d.out_ready_i.read()) out_full_ = false;
  }

  footprint::Widths widths_;
  // k = log2 N of each planned fragment, marcher to averager.
  sc_core::sc_fifo<int> counts_{"counts", kCountDepth};
  uint32_t probes_ = 0;  // wraps, as the counter port
  bool out_full_ = false;
  uint32_t out_rgba_ = 0;
};

}  // namespace tmu::hls
