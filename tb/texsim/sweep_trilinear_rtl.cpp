// The trilinear unit's Verilated width variants in the sweep: which settings have an rtl
// model (rtl/blocks.cmake: the trilinear block's variants), and their speed and agreement with
// golden on the sweep's test pattern (outputs, counters and every memory request).
#include <fmt/format.h>

#include "blocks/trilinear/trilinear_block.hpp"
#include "formats/formats.hpp"
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

}  // namespace tmu::texsim
