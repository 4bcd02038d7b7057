// SystemC model of the footprint assembly unit (000 §10, eq. 19-22, Figs. 12-13), the same
// ports (TMU_SC_PORTS: tb/blocks/footprint/footprint.json) and handshakes as
// rtl/footprint/tmu_footprint.sv. The marcher's probes and the averager are
// footprint_march_sc.hpp's (golden's plan, probe and average); the probes are sampled by an
// instance of the TEXRAM trilinear unit's model (hls/texram/trilinear_sc.hpp), whose memory port
// is the unit's. Two clocked threads:
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

#include <cstdint>
#include <systemc>

#include "blocks/footprint/footprint_ports.hpp"
#include "footprint/footprint.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/footprint/footprint_march_sc.hpp"
#include "hls/texram/trilinear_sc.hpp"

namespace tmu::hls {

class FootprintSc : public FootprintMarchSc<FootprintSc> {
 public:
  TMU_SC_PORTS(footprint)

  SC_HAS_PROCESS(FootprintSc);
  FootprintSc(sc_core::sc_module_name name, const footprint::Widths& widths = {},
              const texram::Widths& trilinear_widths = {})
      : FootprintMarchSc(name, widths), tri_("trilinear", trilinear_widths) {
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
    tri_.req_valid_i(probe_valid_);
    tri_.req_ready_o(probe_ready_);
    tri_.req_u_i(probe_u_);
    tri_.req_v_i(probe_v_);
    tri_.req_lambda_i(probe_lambda_);
    tri_.req_shade_i(probe_shade_);
    tri_.mem_req_valid_o(mem_req_valid_o);
    tri_.mem_req_ready_i(mem_req_ready_i);
    tri_.mem_req_en_o(mem_req_en_o);
    tri_.mem_req_addr_o(mem_req_addr_o);
    tri_.mem_resp_valid_i(mem_resp_valid_i);
    tri_.mem_resp_data_i(mem_resp_data_i);
    tri_.out_valid_o(result_valid_);
    tri_.out_ready_i(result_ready_);
    tri_.out_rgba_o(result_rgba_);

    SC_CTHREAD(march, clk_i.pos());
    reset_signal_is(rst_ni, false);
    SC_CTHREAD(collect, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void march() {
    // Reset. Not ready: the edge that leaves reset is spent here.
    clut_ready_o.write(false);
    req_ready_o.write(false);
    tri_clut_valid_.write(false);
    tri_clut_addr_.write(0);
    tri_clut_rgba_.write(0);
    reset_probes();
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
      if (write) {
        tri_clut_addr_.write(clut_addr);
        tri_clut_rgba_.write(clut_rgba);
        tri_clut_valid_.write(true);
        do {
          wait();
        } while (!tri_clut_ready_.read());
        tri_clut_valid_.write(false);
      }
      if (fragment) issue(request, footprint::plan(request, config), sampler);
    }
  }

  TrilinearSc tri_;
  sc_core::sc_signal<bool> tri_clut_valid_{"tri_clut_valid"}, tri_clut_ready_{"tri_clut_ready"};
  sig<formats::kClutIndex.width()> tri_clut_addr_{"tri_clut_addr"};
  sig<formats::kRgba8888.width()> tri_clut_rgba_{"tri_clut_rgba"};
  sig<formats::kTexAddressing.width()> tri_addressing_{"tri_addressing"};  // 0: texel
};

}  // namespace tmu::hls
