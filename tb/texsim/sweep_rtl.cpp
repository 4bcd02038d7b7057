// The sweeps' hardware against golden (sweep_support.hpp): the trilinear unit's Verilated width
// variants on the sweep's own test pattern (which settings have an rtl model: rtl/blocks.cmake,
// the trilinear block's variants), and any block at a sweep's setting through the
// co-simulation flow of `texsim cosim`.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "blocks/trilinear/trilinear_block.hpp"
#include "formats/formats.hpp"
#include "harness/cosim.hpp"
#include "texram/floor_view.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {

RtlSpeed measure_trilinear_rtl(const texram::Widths& widths, const texram::TexramTexture& texture,
                               const texram::SamplerConfig& config, const SweepArgs&) {
  texram::SamplerConfig at = config;
  at.widths = widths;
  const tb::TrilinearBlock block(
      tb::BlockOptions{},
      {std::make_shared<const texram::TexramTexture>(texture), at, "sweep pattern"});
  std::unique_ptr<tb::Engine> rtl;
  try {
    rtl = block.engine("rtl");
  } catch (const std::invalid_argument&) {
    return {};  // no model was verilated at these widths
  }
  std::vector<tb::Txn> items = block.setup_items();
  for (const auto& v : texram::floor_view(256, 192, texture.geometry.texel_width(0),
                                          texture.geometry.texel_height(0))) {
    items.push_back(
        tb::trilinear_sample_item(static_cast<int32_t>(formats::TexCoord::from_double(v.u).raw()),
                                  static_cast<int32_t>(formats::TexCoord::from_double(v.v).raw()),
                                  static_cast<int32_t>(formats::Lod::from_double(v.lambda).raw())));
  }
  const tb::RunResult golden = block.engine("golden")->run(items, tb::RunOptions{});
  const tb::RunResult r = rtl->run(items, tb::RunOptions{});
  RtlSpeed out;
  out.samples_per_second = r.error.empty() ? static_cast<double>(r.outputs.size()) / r.seconds : 0;
  out.verdict = r.error.empty() && golden.error.empty() && r.outputs == golden.outputs &&
                        r.counters == golden.counters && r.requests == golden.requests
                    ? "yes"
                    : "NO";
  return out;
}

std::string RtlCheck::verdict() const {
  if (simulator.empty()) return "no model";
  if (!match) return "NO";
  return simulator == "icarus" ? "yes (Icarus)" : "yes";
}

namespace {

// The simulator the block has at its setting: Verilator's model, else Icarus Verilog's.
std::string simulator_of(const tb::Block& block) {
  for (const char* level : {"rtl", "icarus"}) {
    try {
      block.engine(level);
      return level;
    } catch (const std::invalid_argument&) {
      // not at this setting (or Icarus not installed)
    }
  }
  return "";
}

}  // namespace

RtlCheck check_rtl(const std::string& block_name, const tb::BlockOptions& options, size_t count) {
  std::unique_ptr<tb::Block> block;
  try {
    block = tb::make_block(block_name, options);
  } catch (const std::invalid_argument&) {
    return {};  // a setting beyond the block's ports: no hardware model takes it
  }
  RtlCheck check;
  check.simulator = simulator_of(*block);
  if (!check.simulator.empty()) {
    tb::CosimOptions o;
    o.count = check.simulator == "icarus" ? std::min(count, kIcarusItems) : count;
    o.engines = {check.simulator};
    o.in_idle = o.out_stall = 0;  // full rate: the runs' cycles are the unit's throughput
    o.x_check = false;            // the conformance suite's business, not a figure's
    o.wave_dir = (std::filesystem::temp_directory_path() / "tmu_sweep_cosim").string();
    std::ostringstream log;
    const tb::CosimResult r = tb::run_cosim(*block, o, log);
    check.match = r.pass;
    check.run = r.runs.at(check.simulator);
    if (!r.pass) std::cout << "sweep: " << block_name << " differs from golden:\n" << log.str();
  }
  return check;
}

}  // namespace tmu::texsim
