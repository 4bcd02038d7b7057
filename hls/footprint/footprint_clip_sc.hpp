// SystemC model of footprint assembly on a clip-map (000 §10 in front of 003), the same ports
// (TMU_SC_PORTS: tb/blocks/footprint_clip/footprint_clip.json) and handshakes as
// rtl/footprint/tmu_footprint_clip.sv: the footprint unit's marcher and averager
// (footprint_march_sc.hpp, as footprint_sc.hpp) with the probes sampled by an instance of the
// clip-map unit's model (hls/texram/clipmap_sc.hpp), whose memory port and counters are the
// unit's.
//
// - the setup/marcher: while idle it takes a CLUT, region or load write (the first offered) or a
//   fragment (both at one edge: the write is passed first). A write is passed to the clip-map's
//   port (held until taken); the marcher holds no fragment then, so every probe before it has
//   been taken by the clip-map, which orders its ports with the samples it holds. A fragment's
//   N probes are presented one per clock to the clip-map (each held until taken).
// - the averager: pops k from the count FIFO, collects the clip-map's next N results, averages
//   them and loads a one-entry ready/valid output register.
//
// Sequential per probe: only the transactions, the memory accesses and the counters match the
// RTL, not its timing. The setup's widths are a constructor argument, as the RTL's parameters.
#pragma once

#include <cstdint>
#include <systemc>

#include "blocks/footprint_clip/footprint_clip_ports.hpp"
#include "footprint/footprint.hpp"
#include "formats/formats.hpp"
#include "hls/common/sc_ports.hpp"
#include "hls/footprint/footprint_march_sc.hpp"
#include "hls/texram/clipmap_sc.hpp"

namespace tmu::hls {

class FootprintClipSc : public FootprintMarchSc<FootprintClipSc> {
 public:
  TMU_SC_PORTS(footprint_clip)

  SC_HAS_PROCESS(FootprintClipSc);
  FootprintClipSc(sc_core::sc_module_name name, const footprint::Widths& widths = {})
      : FootprintMarchSc(name, widths), clip_("clipmap") {
    clip_.clk_i(clk_i);
    clip_.rst_ni(rst_ni);
    clip_.cfg_log2_virtual_i(cfg_log2_virtual_i);
    clip_.cfg_log2_tile_i(cfg_log2_tile_i);
    clip_.cfg_kind_i(cfg_kind_i);
    clip_.cfg_single_channel_i(cfg_single_channel_i);
    clip_.cfg_filter_i(cfg_filter_i);
    clip_.cfg_border_u_i(cfg_border_u_i);
    clip_.cfg_border_v_i(cfg_border_v_i);
    clip_.cfg_border_rgba_i(cfg_border_rgba_i);
    clip_.cfg_combine_i(cfg_combine_i);
    clip_.cfg_constant_rgba_i(cfg_constant_rgba_i);
    clip_.cfg_substitution_i(cfg_substitution_i);
    clip_.clut_valid_i(clip_clut_valid_);
    clip_.clut_ready_o(clip_clut_ready_);
    clip_.clut_addr_i(clip_clut_addr_);
    clip_.clut_rgba_i(clip_clut_rgba_);
    clip_.region_valid_i(clip_region_valid_);
    clip_.region_ready_o(clip_region_ready_);
    clip_.region_level_i(clip_region_level_);
    clip_.region_x0_i(clip_region_x0_);
    clip_.region_y0_i(clip_region_y0_);
    clip_.region_x1_i(clip_region_x1_);
    clip_.region_y1_i(clip_region_y1_);
    clip_.load_valid_i(clip_load_valid_);
    clip_.load_ready_o(clip_load_ready_);
    clip_.load_level_i(clip_load_level_);
    clip_.load_x_i(clip_load_x_);
    clip_.load_y_i(clip_load_y_);
    clip_.load_texel_i(clip_load_texel_);
    clip_.req_valid_i(probe_valid_);
    clip_.req_ready_o(probe_ready_);
    clip_.req_u_i(probe_u_);
    clip_.req_v_i(probe_v_);
    clip_.req_lambda_i(probe_lambda_);
    clip_.req_shade_i(probe_shade_);
    clip_.mem_req_valid_o(mem_req_valid_o);
    clip_.mem_req_ready_i(mem_req_ready_i);
    clip_.mem_req_en_o(mem_req_en_o);
    clip_.mem_req_addr_o(mem_req_addr_o);
    clip_.mem_req_we_o(mem_req_we_o);
    clip_.mem_req_wdata_o(mem_req_wdata_o);
    clip_.mem_resp_valid_i(mem_resp_valid_i);
    clip_.mem_resp_data_i(mem_resp_data_i);
    clip_.out_valid_o(result_valid_);
    clip_.out_ready_i(result_ready_);
    clip_.out_rgba_o(result_rgba_);
    clip_.stat_wayward_samples_o(stat_wayward_samples_o);
    clip_.stat_substituted_taps_o(stat_substituted_taps_o);
    clip_.stat_conflicts_o(stat_conflicts_o);

    SC_CTHREAD(march, clk_i.pos());
    reset_signal_is(rst_ni, false);
    SC_CTHREAD(collect, clk_i.pos());
    reset_signal_is(rst_ni, false);
  }

 private:
  void march() {
    // Reset. Not ready: the edge that leaves reset is spent here.
    set_ready(false);
    clip_clut_valid_.write(false);
    clip_region_valid_.write(false);
    clip_load_valid_.write(false);
    reset_probes();
    wait();
    while (true) {
      // Idle: a write or a fragment (or both: the write is then passed first).
      set_ready(true);
      wait();
      set_ready(false);
      const bool fragment = req_valid_i.read();
      // Everything taken at this edge is read now: the inputs may change after it.
      const footprint::Request request = fragment_request();
      const footprint::Config config = footprint_config();
      const texram::SamplerConfig sampler = sampler_config();
      if (clut_valid_i.read()) {
        clip_clut_addr_.write(clut_addr_i.read());
        clip_clut_rgba_.write(clut_rgba_i.read());
        pass(clip_clut_valid_, clip_clut_ready_);
      } else if (region_valid_i.read()) {
        clip_region_level_.write(region_level_i.read());
        clip_region_x0_.write(region_x0_i.read());
        clip_region_y0_.write(region_y0_i.read());
        clip_region_x1_.write(region_x1_i.read());
        clip_region_y1_.write(region_y1_i.read());
        pass(clip_region_valid_, clip_region_ready_);
      } else if (load_valid_i.read()) {
        clip_load_level_.write(load_level_i.read());
        clip_load_x_.write(load_x_i.read());
        clip_load_y_.write(load_y_i.read());
        clip_load_texel_.write(load_texel_i.read());
        pass(clip_load_valid_, clip_load_ready_);
      }
      if (fragment) issue(request, footprint::plan(request, config), sampler);
    }
  }

  // Every input port is ready while the marcher is idle.
  void set_ready(bool ready) {
    clut_ready_o.write(ready);
    region_ready_o.write(ready);
    load_ready_o.write(ready);
    req_ready_o.write(ready);
  }

  // A write to the clip-map's port, held until taken.
  void pass(sc_core::sc_signal<bool>& valid, const sc_core::sc_signal<bool>& ready) {
    valid.write(true);
    do {
      wait();
    } while (!ready.read());
    valid.write(false);
  }

  ClipmapSc clip_;
  sc_core::sc_signal<bool> clip_clut_valid_{"clip_clut_valid"}, clip_clut_ready_{"clip_clut_ready"};
  sig<formats::kClutIndex.width()> clip_clut_addr_{"clip_clut_addr"};
  sig<formats::kRgba8888.width()> clip_clut_rgba_{"clip_clut_rgba"};
  sc_core::sc_signal<bool> clip_region_valid_{"clip_region_valid"},
      clip_region_ready_{"clip_region_ready"};
  sig<formats::kMipLevel.width()> clip_region_level_{"clip_region_level"};
  sig<formats::kClipBound.width()> clip_region_x0_{"clip_region_x0"},
      clip_region_y0_{"clip_region_y0"}, clip_region_x1_{"clip_region_x1"},
      clip_region_y1_{"clip_region_y1"};
  sc_core::sc_signal<bool> clip_load_valid_{"clip_load_valid"}, clip_load_ready_{"clip_load_ready"};
  sig<formats::kMipLevel.width()> clip_load_level_{"clip_load_level"};
  sig<formats::kClipCoord.width()> clip_load_x_{"clip_load_x"}, clip_load_y_{"clip_load_y"};
  sig<formats::kRgba8888.width()> clip_load_texel_{"clip_load_texel"};
};

}  // namespace tmu::hls
