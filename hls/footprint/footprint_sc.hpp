// SystemC model of the footprint assembly unit (000 §10, eq. 19-22, Figs. 12-13), the same
// ports (TMU_SC_PORTS: tb/blocks/footprint/footprint.json) and handshakes as
// rtl/footprint/tmu_footprint.sv. Its arithmetic is the golden model's
// (golden/footprint/footprint.hpp: plan for the setup, probe for each probe's position,
// average for the result); the probes are sampled by an instance of the TEXRAM trilinear unit's
// model (hls/texram/trilinear_sc.hpp), whose memory port is the unit's. Two clocked threads:
//
// - the setup/marcher: while idle it takes a CLUT write or a fragment (both at one edge: the
//   write is ordered first). A CLUT write is passed to the trilinear unit's CLUT port (held
//   until taken); since the marcher holds no fragment then, every probe before it has been
//   taken by the unit, which serves its inputs in order. A fragment is planned
//   (footprint::plan), its probe count k = log2 N is pushed into the count FIFO, and its N
//   probes are presented one per clock to the trilinear unit (each held until taken; the
//   unit's ready paces them). stat_probes_o counts the probes taken since reset (wraps).
// - the averager: pops k from the count FIFO, collects the unit's next N results, averages
//   them (footprint::average) and loads a one-entry ready/valid output register.
//
// It is sequential per probe (the trilinear model serves one sample at a time); only the
// transactions and the memory accesses match the RTL, not its timing.
//
// The configuration (cfg_*) is quasi-static: the footprint's part is read when a fragment is
// accepted, the trilinear unit's when each probe is. A cfg_log2_max_probes_i above
// formats::kMaxProbeLog2 acts as kMaxProbeLog2. The setup's widths (footprint::Widths) and the
// trilinear unit's (texram::Widths) are constructor arguments, as the RTL's parameters; bad
// footprint widths throw std::invalid_argument at construction.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <systemc>

#include "blocks/footprint/footprint_ports.hpp"
#include "footprint/footprint.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/texram/trilinear_sc.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::hls {

class FootprintSc : public sc_core::sc_module {
 public:
  // Fragments planned whose results the averager has not yet collected, at most.
  static constexpr int kCountDepth = 4;

  TMU_SC_PORTS(footprint)

  SC_HAS_PROCESS(FootprintSc);
  FootprintSc(sc_core::sc_module_name name, const footprint::Widths& widths = {},
              const texram::Widths& trilinear_widths = {})
      : sc_core::sc_module(name), widths_(widths), tri_("trilinear", trilinear_widths) {
    // plan() checks the widths: fail at elaboration, not in the middle of a run.
    (void)footprint::plan(footprint::Request{},
                          footprint::Config{0, footprint::QRule::kHeights, widths_});
    tri_.clk_i(clk_i);
    tri_.rst_ni(rst_ni);
    tri_.cfg_log2_w_i(cfg_log2_w_i);
    tri_.cfg_log2_h_i(cfg_log2_h_i);
    tri_.cfg_kind_i(cfg_kind_i);
    tri_.cfg_single_channel_i(cfg_single_channel_i);
    tri_.cfg_filter_i(cfg_filter_i);
    tri_.cfg_border_u_i(cfg_border_u_i);
    tri_.cfg_border_v_i(cfg_border_v_i);
    tri_.cfg_border_rgba_i(cfg_border_rgba_i);
    tri_.cfg_combine_i(cfg_combine_i);
    tri_.cfg_constant_rgba_i(cfg_constant_rgba_i);
    tri_.cfg_addressing_i(tri_addressing_);  // texel: the probes are texels
    tri_.clut_valid_i(tri_clut_valid_);
    tri_.clut_ready_o(tri_clut_ready_);
    tri_.clut_addr_i(tri_clut_addr_);
    tri_.clut_rgba_i(tri_clut_rgba_);
    tri_.req_valid_i(tri_req_valid_);
    tri_.req_ready_o(tri_req_ready_);
    tri_.req_u_i(tri_req_u_);
    tri_.req_v_i(tri_req_v_);
    tri_.req_lambda_i(tri_req_lambda_);
    tri_.req_shade_i(tri_req_shade_);
    tri_.mem_req_valid_o(mem_req_valid_o);
    tri_.mem_req_ready_i(mem_req_ready_i);
    tri_.mem_req_en_o(mem_req_en_o);
    tri_.mem_req_addr_o(mem_req_addr_o);
    tri_.mem_resp_valid_i(mem_resp_valid_i);
    tri_.mem_resp_data_i(mem_resp_data_i);
    tri_.out_valid_o(tri_out_valid_);
    tri_.out_ready_i(tri_out_ready_);
    tri_.out_rgba_o(tri_out_rgba_);

    SC_CTHREAD(march, clk_i.pos());
    reset_signal_is(rst_ni, false);
    SC_CTHREAD(collect, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  // ---- setup / marcher --------------------------------------------------------------------

  void march() {
    // Reset. Not ready: the edge that leaves reset is spent here.
    clut_ready_o.write(false);
    req_ready_o.write(false);
    tri_clut_valid_.write(false);
    tri_clut_addr_.write(0);
    tri_clut_rgba_.write(0);
    tri_req_valid_.write(false);
    tri_req_u_.write(0);
    tri_req_v_.write(0);
    tri_req_lambda_.write(0);
    tri_req_shade_.write(0);
    probes_ = 0;
    stat_probes_o.write(0);
    wait();
    while (true) {
      // Idle: a CLUT write or a fragment (or both: the write is then passed first).
      clut_ready_o.write(true);
      req_ready_o.write(true);
      wait();
      clut_ready_o.write(false);
      req_ready_o.write(false);
      const bool write = clut_valid_i.read();
      const bool fragment = req_valid_i.read();
      // Everything taken at this edge is read now: the inputs may change after it.
      const auto clut_addr = clut_addr_i.read();
      const auto clut_rgba = clut_rgba_i.read();
      const footprint::Request request = fragment_request();
      const footprint::Config config = footprint_config();
      const texram::SamplerConfig sampler = sampler_config();
      if (write) pass_clut_write(clut_addr, clut_rgba);
      if (fragment) issue(request, footprint::plan(request, config), sampler);
    }
  }

  footprint::Request fragment_request() const {
    const auto coord = [](const auto& port) {
      return static_cast<int32_t>(signed_value(port.read(), fmts::kTexCoord));
    };
    const auto deriv = [](const auto& port) {
      return static_cast<int32_t>(signed_value(port.read(), fmts::kTexDeriv));
    };
    footprint::Request r;
    r.u = coord(req_u_i);
    r.v = coord(req_v_i);
    r.r1u = deriv(req_r1u_i);
    r.r1v = deriv(req_r1v_i);
    r.r2u = deriv(req_r2u_i);
    r.r2v = deriv(req_r2v_i);
    r.shade = static_cast<uint32_t>(req_shade_i.read());
    return r;
  }

  footprint::Config footprint_config() const {
    footprint::Config c;
    c.log2_max_probes =
        std::min(static_cast<int>(cfg_log2_max_probes_i.read().to_uint()), fmts::kMaxProbeLog2);
    c.q_rule = static_cast<footprint::QRule>(cfg_q_rule_i.read().to_uint());
    c.widths = widths_;
    return c;
  }

  // probe() needs the border modes (a coordinate beyond the port wraps or saturates).
  texram::SamplerConfig sampler_config() const {
    texram::SamplerConfig c;
    c.border_u = static_cast<texram::Border>(cfg_border_u_i.read().to_uint());
    c.border_v = static_cast<texram::Border>(cfg_border_v_i.read().to_uint());
    return c;
  }

  void pass_clut_write(const sc_port_t<fmts::kClutIndex.width()>& addr,
                       const sc_port_t<fmts::kRgba8888.width()>& rgba) {
    tri_clut_addr_.write(addr);
    tri_clut_rgba_.write(rgba);
    tri_clut_valid_.write(true);
    do {
      wait();
    } while (!tri_clut_ready_.read());
    tri_clut_valid_.write(false);
  }

  // The fragment's probes to the trilinear unit, one per clock while it takes them.
  void issue(const footprint::Request& request, const footprint::Plan& plan,
             const texram::SamplerConfig& sampler) {
    while (!counts_.nb_write(plan.log2_n)) wait();  // the averager is kCountDepth behind
    const int n = 1 << plan.log2_n;
    for (int i = 0; i < n; ++i) {
      const texram::Request q = footprint::probe(request, plan, i, sampler);
      // Raw port bits (the trilinear unit's ports are its description's).
      tri_req_u_.write(static_cast<uint32_t>(q.u) & ((1u << fmts::kTexCoord.width()) - 1));
      tri_req_v_.write(static_cast<uint32_t>(q.v) & ((1u << fmts::kTexCoord.width()) - 1));
      tri_req_lambda_.write(static_cast<uint32_t>(q.lambda) & ((1u << fmts::kLod.width()) - 1));
      tri_req_shade_.write(q.shade);
      tri_req_valid_.write(true);
      do {
        wait();
      } while (!tri_req_ready_.read());
      ++probes_;
      stat_probes_o.write(probes_);
    }
    tri_req_valid_.write(false);
  }

  // ---- averager ---------------------------------------------------------------------------

  void collect() {
    out_valid_o.write(false);
    out_rgba_o.write(0);
    tri_out_ready_.write(false);
    out_full_ = false;
    out_rgba_ = 0;
    for (int stale = 0; counts_.nb_read(stale);) {
    }
    wait();
    while (true) {
      int log2_n = 0;
      while (!counts_.nb_read(log2_n)) step();
      const int n = 1 << log2_n;
      std::array<uint32_t, size_t{1} << fmts::kMaxProbeLog2> colours{};
      tri_out_ready_.write(true);
      for (int i = 0; i < n;) {
        step();
        if (tri_out_valid_.read()) {
          colours[static_cast<size_t>(i++)] = static_cast<uint32_t>(tri_out_rgba_.read());
        }
      }
      tri_out_ready_.write(false);
      const uint32_t rgba =
          footprint::average(std::span(colours.data(), static_cast<size_t>(n)), log2_n);
      while (out_full_) step();
      out_full_ = true;
      out_rgba_ = rgba;
    }
  }

  // One clock of the averager: present the output register, wait for the edge, and retire
  // the output if it was taken. Reads after it see the inputs from before the edge.
  void step() {
    out_valid_o.write(out_full_);
    out_rgba_o.write(out_rgba_);
    wait();
    if (out_full_ && out_ready_i.read()) out_full_ = false;
  }

  template <int W>
  using sig = sc_core::sc_signal<sc_port_t<W>>;

  footprint::Widths widths_;
  TrilinearSc tri_;
  sc_core::sc_signal<bool> tri_clut_valid_{"tri_clut_valid"}, tri_clut_ready_{"tri_clut_ready"};
  sig<fmts::kClutIndex.width()> tri_clut_addr_{"tri_clut_addr"};
  sig<fmts::kRgba8888.width()> tri_clut_rgba_{"tri_clut_rgba"};
  sig<fmts::kTexAddressing.width()> tri_addressing_{"tri_addressing"};  // 0: texel
  sc_core::sc_signal<bool> tri_req_valid_{"tri_req_valid"}, tri_req_ready_{"tri_req_ready"};
  sig<fmts::kTexCoord.width()> tri_req_u_{"tri_req_u"}, tri_req_v_{"tri_req_v"};
  sig<fmts::kLod.width()> tri_req_lambda_{"tri_req_lambda"};
  sig<fmts::kRgba8888.width()> tri_req_shade_{"tri_req_shade"};
  sc_core::sc_signal<bool> tri_out_valid_{"tri_out_valid"}, tri_out_ready_{"tri_out_ready"};
  sig<fmts::kRgba8888.width()> tri_out_rgba_{"tri_out_rgba"};
  // k = log2 N of each planned fragment, marcher to averager.
  sc_core::sc_fifo<int> counts_{"counts", kCountDepth};

  uint32_t probes_ = 0;  // wraps, as the counter port
  bool out_full_ = false;
  uint32_t out_rgba_ = 0;
};

}  // namespace tmu::hls
