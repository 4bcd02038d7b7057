// The trilinear unit's Verilated width variants in the sweep: which settings have an rtl
// model (rtl/CMakeLists.txt builds them from one list and generates the header naming them),
// and their speed and agreement with golden on the sweep's test pattern.
#include <fmt/format.h>

#include "blocks/trilinear_block.hpp"
#include "formats/formats.hpp"
#include "texram/floor_view.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

// The block's rtl engine at these widths, or nothing when no model was verilated for them.
std::unique_ptr<tb::Engine> rtl_engine(const texram::Widths& w, const tb::TrilinearEnv& env) {
  tb::TrilinearEnv at = env;
  at.config.widths = w;
  try {
    return tb::TrilinearBlock(tb::BlockOptions{}, at).engine("rtl");
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
}

}  // namespace

RtlSpeed measure_trilinear_rtl(const texram::Widths& widths, const texram::TexramTexture& texture,
                               const texram::SamplerConfig& config, const SweepArgs&) {
  tb::TrilinearEnv env{std::make_shared<const texram::TexramTexture>(texture), config,
                       "sweep pattern"};
  const auto rtl = rtl_engine(widths, env);
  if (!rtl) return {};
  std::vector<tb::Txn> items = tb::trilinear_clut_load(texture);
  for (const auto& v : texram::floor_view(256, 192, texture.geometry.texel_width(0),
                                          texture.geometry.texel_height(0))) {
    items.push_back(
        tb::trilinear_sample_item(static_cast<int32_t>(formats::TexCoord::from_double(v.u).raw()),
                                  static_cast<int32_t>(formats::TexCoord::from_double(v.v).raw()),
                                  static_cast<int32_t>(formats::Lod::from_double(v.lambda).raw())));
  }
  tb::BlockOptions options;
  const tb::TrilinearBlock block(options, env);
  const tb::RunResult golden = block.engine("golden")->run(items, tb::RunOptions{});
  const tb::RunResult r = rtl->run(items, tb::RunOptions{});
  RtlSpeed out;
  out.samples_per_second = r.error.empty() ? static_cast<double>(r.outputs.size()) / r.seconds : 0;
  out.verdict = r.error.empty() && r.outputs == golden.outputs && r.counters == golden.counters
                    ? "yes"
                    : "NO";
  return out;
}

}  // namespace tmu::texsim
